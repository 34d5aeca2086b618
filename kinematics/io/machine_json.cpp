#include "kinematics/io/machine_json.h"

namespace linkwright::kinematics::io {

JsonValue machineJson(const MachineRun& run, const MachineRequest& request) {
  const MachineDuty& d = run.duty;
  const DutyOptions& o = request.duty;
  JsonValue json{
      {"omega_rad_s", d.omega}, {"samples", run.samples}, {"tolerance", run.tolerance}, {"converged", run.converged}};
  JsonValue motor{{"gear_ratio", o.gearRatio}, {"efficiency", o.efficiency}, {"speed_rad_s", d.motor.speed}};
  JsonValue accuracy = JsonValue::object();
  for (const DutyFigure& f : dutyFigures(d, o)) {
    (f.group == "motor" ? motor : json)[f.key] = f.value;
    if (f.accuracy) accuracy[f.group.empty() ? f.key : f.group + "." + f.key] = *f.accuracy;
  }
  if (d.flywheelInertia && o.speedFluctuation) {
    json["cs"] = *o.speedFluctuation;
    if (d.flywheelRun) json["cs_by_forward_dynamics"] = d.flywheelRun->speedFluctuation;
  }
  json["virtual_work_difference_Nm"] = d.virtualWorkDifference;
  if (!d.motor.verdict.empty()) motor["verdict"] = d.motor.verdict;
  json["motor"] = motor;
  json["accuracy"] = accuracy;
  return json;
}

}  // namespace linkwright::kinematics::io
