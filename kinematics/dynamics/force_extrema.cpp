#include "kinematics/dynamics/force_extrema.h"

#include <cmath>
#include <limits>
#include <utility>

namespace linkwright::kinematics {

std::optional<Extrema> forceExtrema(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& spec,
                                    const ForceSweep& forces, const PoseForceQuantity& quantity) {
  auto created = InverseDynamics::create(mechanism, dynamics);
  if (!created) return std::nullopt;
  InverseDynamics solver = std::move(created).value();
  std::vector<double> values(forces.size());
  std::vector<bool> valid(forces.size());
  for (std::size_t j = 0; j < forces.size(); ++j) {
    valid[j] = forces.ok(j);
    values[j] = valid[j] ? quantity(forces.at(j)) : 0.0;
  }
  PoseForces probe;
  solver.prepare(probe);
  // A pose between samples whose forces are not determined (a toggle the samples straddle)
  // takes no part: NaN is never chosen by the search.
  const PoseQuantity atPose = [&](const Pose& pose, double input) {
    return solver.solveInto(pose, probe, input) == PoseStatus::Ok ? quantity(probe)
                                                                  : std::numeric_limits<double>::quiet_NaN();
  };
  return refineExtrema(mechanism, spec, values, valid, atPose);
}

std::optional<ShakingPeaks> shakingPeaks(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                         const SweepSpec& spec, const ForceSweep& forces) {
  const auto force =
      forceExtrema(mechanism, dynamics, spec, forces, [](const PoseForces& f) { return f.shakingForce.norm(); });
  const auto moment =
      forceExtrema(mechanism, dynamics, spec, forces, [](const PoseForces& f) { return f.shakingMoment; });
  if (!force || !moment) return std::nullopt;
  const bool lowIsLarger = std::abs(moment->minimum.value) > std::abs(moment->maximum.value);
  return ShakingPeaks{force->maximum, lowIsLarger ? moment->minimum : moment->maximum};
}

}  // namespace linkwright::kinematics
