#pragma once
// A turn's duty as JSON (machine_request.h), written once for linkwright-cli machine --json and
// Python's Linkage.machine: SI units, each figure under its key (dutyFigures), the motor's under
// "motor", and each figure's relative error estimate under "accuracy" ("motor.…" for the
// motor's), with the grid it was read off and whether every estimate is within the tolerance.

#include "kinematics/dynamics/machine_request.h"
#include "kinematics/io/json.h"

namespace linkwright::kinematics::io {

JsonValue machineJson(const MachineRun& run, const MachineRequest& request);

}  // namespace linkwright::kinematics::io
