#include "kinematics/io/balance_json.h"

namespace linkwright::kinematics::io {
namespace {

JsonValue dutyJson(const std::optional<MachineDuty>& d) {
  if (!d) return nullptr;
  return {{"shaking_force_peak_N", d->shakingForcePeak},
          {"shaking_moment_peak_Nm", d->shakingMomentPeak},
          {"rms_torque_Nm", d->rmsTorque},
          {"peak_torque_Nm", d->peakTorque},
          {"bearing_load_peak_N", d->bearingLoadPeak},
          {"accuracy", d->worstAccuracy()}};
}

JsonValue endJson(const SpringEnd& end) {
  return {{"link", end.link.empty() ? JsonValue(nullptr) : JsonValue(end.link)}, {"point", end.point}};
}

}  // namespace

JsonValue balanceJson(const BalanceRun& run, const JsonValue& output) {
  const char* method = run.method == BalanceMethod::Counterweights ? "counterweights"
                       : run.method == BalanceMethod::Spring       ? "spring"
                                                                   : "spring-search";
  JsonValue j{{"method", method}, {"output", output}, {"length_unit", run.balanced.mechanism.lengthUnit}};
  if (run.weights) {
    j["description"] = run.weights->method;
    j["counterweights"] = JsonValue::array();
    for (const Counterweight& c : run.weights->counterweights)
      j["counterweights"].push_back(
          {{"link", c.link}, {"mass_kg", c.mass}, {"along", c.centre.along}, {"across", c.centre.across}});
    j["omega_rad_s"] = run.before ? JsonValue(run.before->omega) : JsonValue(nullptr);
    j["before"] = dutyJson(run.before);
    j["after"] = dutyJson(run.after);
    if (run.before) {
      j["samples"] = run.turnSamples;
      j["converged"] = run.converged;
    }
    if (!run.noTurn.empty()) j["no_turn"] = run.noTurn;
    return j;
  }
  const SpringBalance& b = *run.spring;
  j["spring"] = {{"first", endJson(b.spring.first)},
                 {"second", endJson(b.spring.second)},
                 {"stiffness_N_m", b.spring.stiffness},
                 {"free_length", b.spring.freeLength},
                 {"preload_N", b.spring.preload}};
  j["omega_rad_s"] = run.balanced.omega;
  j["rms_torque_before_Nm"] = b.rmsBefore;
  j["rms_torque_after_Nm"] = b.rmsAfter;
  if (run.placement) {
    const SpringPlacement& p = *run.placement;
    j["on_link"] = {{"point", b.spring.first.point}, {"along", p.onLink.along}, {"across", p.onLink.across}};
    j["on_frame"] = {{"point", b.spring.second.point}, {"position", JsonValue::array({p.onFrame.x(), p.onFrame.y()})}};
    j["at_bound"] = p.atBound;
  }
  return j;
}

}  // namespace linkwright::kinematics::io
