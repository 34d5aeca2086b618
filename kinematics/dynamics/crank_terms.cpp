#include "kinematics/dynamics/crank_terms.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

std::string degreesText(double radians) { return formatShort(radToDeg(radians)) + "°"; }

}  // namespace

std::optional<Error> checkCrankDriven(const Mechanism& mechanism) {
  if (inputKind(mechanism) == InputKind::Angle && driverPoint(mechanism)) return std::nullopt;
  return invalid("driver", "a flywheel, a motor and a turn's torque need a crank: this linkage is driven by its " +
                               inputName(mechanism));
}

std::optional<Error> checkCrankTurn(const Mechanism& mechanism, const SweepSpec& turn) {
  if (auto e = checkCrankDriven(mechanism)) return e;
  if (auto e = checkSweepSpec(turn)) return e;
  if (turn.time) return invalid("time base", "a turn's duty is computed at a constant crank speed, not on a time base");
  if (turn.omega == 0.0) return invalid("omega", "the crank's speed must not be 0 for a turn's duty");
  if (turn.alpha != 0.0)
    return invalid("alpha", "a turn's duty is computed at a constant crank speed (got α = " + formatNumber(turn.alpha) +
                                " rad/s²)");
  const double span = turn.toAngle - turn.fromAngle;
  if (std::abs(std::abs(span) - kTurn) > 1e-9 * kTurn)
    return invalid("range", "a turn's duty needs the grid to span one full turn, 360° (got " + degreesText(span) + ")");
  if (turn.samples < 4 || turn.samples > kMaxTurnSamples)
    return invalid("samples", "a turn's duty needs 4 to 100000 samples (got " + std::to_string(turn.samples) + ")");
  return std::nullopt;
}

Result<TurnSweep> turnForces(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                             double omega, double alpha, const std::atomic<bool>* cancel) {
  SweepSpec spec = turn;
  spec.omega = omega;
  spec.alpha = alpha;
  auto kinematics = sweep(mechanism, spec);
  if (!kinematics) return kinematics.error();
  for (std::size_t j = 0; j < kinematics->size(); ++j)
    if (!kinematics->ok(j))
      return Error{kinematics->assembled(j) ? ErrorCode::Singular : ErrorCode::NotAssemblable, "range",
                   "the crank cannot turn fully at a constant speed: at " + degreesText(kinematics->inputAngle[j]) +
                       (kinematics->assembled(j) ? " the linkage is at a toggle" : " it cannot be assembled")};
  auto forces = sweepForces(mechanism, dynamics, *kinematics, cancel);
  if (!forces) return forces.error();
  for (std::size_t j = 0; j < forces->size(); ++j)
    if (!forces->ok(j))
      return Error{ErrorCode::Singular, "range",
                   "the forces are not determined at " + degreesText(kinematics->inputAngle[j]) +
                       " (a toggle or a redundant structure)"};
  return TurnSweep{std::move(*kinematics), std::move(*forces)};
}

namespace {

PeriodicSeries seriesOf(const std::vector<double>& angle, const std::vector<double>& column) {
  return PeriodicSeries(angle.front(), std::vector<double>(column.begin(), column.end() - 1));
}

}  // namespace

PeriodicSeries CrankTerms::staticSeries() const { return seriesOf(angle, staticTorque); }
PeriodicSeries CrankTerms::inertiaSeries() const { return seriesOf(angle, inertia); }
PeriodicSeries CrankTerms::halfSlopeSeries() const { return seriesOf(angle, halfSlope); }

CrankTerms CrankTerms::everyOther() const {
  CrankTerms half;
  half.omega = omega;
  for (std::size_t j = 0; j < angle.size(); j += 2) {
    half.angle.push_back(angle[j]);
    half.torque.push_back(torque[j]);
    half.staticTorque.push_back(staticTorque[j]);
    half.inertia.push_back(inertia[j]);
    half.halfSlope.push_back(halfSlope[j]);
  }
  return half;
}

Result<CrankTerms> crankTerms(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                              const ForceSweep& moving, const std::atomic<bool>* cancel) {
  if (auto e = checkCrankTurn(mechanism, turn)) return *e;
  const auto resting = turnForces(mechanism, dynamics, turn, 0.0, 0.0, cancel);
  if (!resting) return resting.error();
  const auto accelerating = turnForces(mechanism, dynamics, turn, 0.0, 1.0, cancel);
  if (!accelerating) return accelerating.error();
  CrankTerms terms;
  terms.omega = turn.omega;
  for (std::size_t j = 0; j < turn.samples; ++j) {
    const double ts = resting->forces.driveTorque[j];
    terms.angle.push_back(sweepAngle(turn, j));
    terms.torque.push_back(moving.driveTorque[j]);
    terms.staticTorque.push_back(ts);
    terms.inertia.push_back(accelerating->forces.driveTorque[j] - ts);
    terms.halfSlope.push_back((moving.driveTorque[j] - ts) / (turn.omega * turn.omega));
  }
  if (terms.angle.back() < terms.angle.front())
    for (auto* c : {&terms.angle, &terms.torque, &terms.staticTorque, &terms.inertia, &terms.halfSlope})
      std::reverse(c->begin(), c->end());
  return terms;
}

}  // namespace linkwright::kinematics
