#pragma once
// Structural and numeric validation of a Mechanism, run once at the boundary (builders,
// loaders) so that the solvers can assume a valid model and neither throw nor allocate.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <optional>

namespace linkwright::kinematics {

/// The first problem found, naming the field ("points[3].firstLength"), or nullopt if the
/// mechanism is valid: unique non-empty names, ids referring to earlier points, exactly one
/// crank, positive finite lengths, finite coordinates, links joining rigidly connected points.
/// Also runs checkLinkageScale.
std::optional<Error> checkMechanism(const Mechanism& mechanism);

/// Error unless the linkage's largest dimension (a length or a coordinate, in its unit) is at
/// most kMaxLengthRatio times its shortest length (validate.h says why). Assumes each number
/// passed its own check. The builders run it on what they build.
std::optional<Error> checkLinkageScale(const Mechanism& mechanism);

}  // namespace linkwright::kinematics
