#pragma once
// The time ratio of a quick-return linkage and the angle it sets in the limit-position
// constructions: with a crank turning steadily, Q = slow stroke / quick stroke = (π + α)/(π − α),
// so α = π (Q − 1)/(Q + 1) is the angle the crank pivot sees between the output's two extreme
// positions (the chord C1C2 subtends α at O2). Q = 1 gives α = 0: the pivot lies on the line
// C1C2 extended.

#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// The largest time ratio a synthesis accepts: at Q = 100 the quick stroke takes 3.6° of crank.
inline constexpr double kMaxTimeRatio = 100.0;

/// Error naming `field` unless 1 ≤ Q ≤ kMaxTimeRatio (finite).
std::optional<Error> checkTimeRatio(double timeRatio, const std::string& field = "timeRatio");

/// α = π (Q − 1)/(Q + 1), rad in [0, π), for a valid Q.
double timeRatioAngle(double timeRatio);

}  // namespace linkwright::kinematics
