#pragma once
// What an optimisation of a linkage minimises or maximises (optimise_linkage.h), each measured
// on the design's own analysis grid by the ordinary sweep (sweep.h), so that the number a user
// reads after the optimisation is the number any analysis of the new design gives:
//   peak |α|: max |α_link| over the grid's range where the rates exist, minimised: the
//     samples bracket the peak and it is refined between them on solved poses (extrema.h, as
//     `extremes` prints it), so it is exact, not the samples' largest;
//   transmission: the worst min(μ, π − μ) over every joint with a transmission angle,
//     maximised; for a recognised four-bar on an angle grid exact in closed form over the
//     grid's crank range (transmission.h, worstTransmissionBetween), for any other linkage
//     refined between the samples as peak |α| is;
//   path: the distance of each target point from the named point's path, which is the polyline
//     through the point's positions at the grid's samples (a target's distance is that to the
//     nearest segment), and of those distances the worst (max) or the RMS √(Σd²/n), minimised;
//   RMS torque: the driving torque's RMS over one turn at the design's ω, as the machine duty
//     computes it (machine_duty.h: inverse dynamics with the design's masses, the trapezoidal
//     rule), minimised.
// Each also gives its curve over the cycle (the quantity at every sample; for a path the path
// itself), so a window can draw the objective before and after.

#include "kinematics/design/design.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

enum class ObjectiveKind {
  PeakAlpha,     ///< minimise max |α| of `link` (rad/s²)
  Transmission,  ///< maximise the worst min(μ, π − μ) (rad)
  Path,          ///< minimise the distance of `point`'s path from `targets` (length unit)
  RmsTorque,     ///< minimise the RMS driving torque over a turn (N·m); needs masses
};

/// How a target path's distances become one number.
enum class PathMeasure {
  Worst,  ///< the largest target's distance
  Rms,    ///< √(mean of the squared distances)
};

/// What to optimise.
struct OptimiseObjective {
  ObjectiveKind kind = ObjectiveKind::PeakAlpha;
  std::string link;                      ///< PeakAlpha: the link, by name
  std::string point = "P";               ///< Path: the point whose path is compared, by name
  std::vector<Eigen::Vector2d> targets;  ///< Path: the target points (length unit, world frame)
  PathMeasure measure = PathMeasure::Worst;
  bool operator==(const OptimiseObjective&) const = default;
};

/// The objective's quantity over the cycle. For Path: x, y are the point's positions (length
/// unit). Otherwise x is the sample's input (a crank's angle in rad, a linear driver's position
/// in the length unit, or the instant in s on a time base; for RmsTorque the turn's crank angle,
/// rad) and y the quantity there: α (rad/s²), the worst min(μ, π − μ) (rad), the torque (N·m).
/// Samples where it does not exist (rates at a toggle) are left out.
struct ObjectiveCurve {
  std::vector<double> x;
  std::vector<double> y;
  bool operator==(const ObjectiveCurve&) const = default;
};

/// The objective's value and curve for one design.
struct ObjectiveValue {
  double value = 0.0;  ///< rad/s², rad, length unit or N·m, as ObjectiveKind says
  ObjectiveCurve curve;
};

/// True for the objectives where larger is better (Transmission).
bool maximised(ObjectiveKind kind);

/// "peak |α|", "worst transmission angle", "distance from the target path", "RMS driving torque".
std::string objectiveName(const OptimiseObjective& objective);

/// Error naming the field ("objective.link", "objective.point", "objective.targets",
/// "objective.targets[2].x", "dynamics") if `objective` cannot be measured on `design`: an
/// unknown link or point, no target or a non-finite one, masses missing for the torque, no dyad
/// for the transmission angle.
std::optional<Error> checkObjective(const Design& design, const OptimiseObjective& objective);

/// The objective of `design`, whose sweep over its grid (designSweepSpec, the default request)
/// is `sweep`; nothing when it cannot be measured there (no sample with rates, the torque's
/// inverse dynamics failing). Assumes checkObjective passed.
std::optional<ObjectiveValue> measureObjective(const Design& design, const OptimiseObjective& objective,
                                               const SweepResult& sweep);

}  // namespace linkwright::kinematics
