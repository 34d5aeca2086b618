#pragma once
// Test helpers: Eigen-aware closeness with the failing component in the message, the seeds'
// mechanisms solved at one crank angle, absolute-margin Approx, angle differences across the
// ±180° seam, a NaN/inf scan of a sweep's columns, and central differences in time of a
// pose's positions for checking the solver's analytic rates.

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

namespace linkwright::test {

/// Passes when |a − b| ≤ tolerance in both components; otherwise names both vectors.
inline bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double tolerance, std::string* why = nullptr) {
  const bool ok = std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
  if (!ok && why != nullptr) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << a.x() << ", " << a.y() << ") vs (" << b.x() << ", " << b.y() << "), tolerance " << tolerance;
    *why = s.str();
  }
  return ok;
}

/// Solves a four-bar at one crank state; fails the test if it does not assemble.
inline kinematics::Pose solveFourBar(const kinematics::FourBarLengths& lengths, kinematics::Branch branch,
                                     double crankAngle, double omega, double alpha = 0.0) {
  const auto mechanism = kinematics::makeFourBar(lengths, branch);
  REQUIRE(mechanism.ok());
  const auto pose = kinematics::solvePose(*mechanism, {crankAngle, omega, alpha});
  INFO((pose.ok() ? std::string() : pose.error().message));
  REQUIRE(pose.ok());
  return *pose;
}

/// The seeds' four-bars (mm): thesis 000 and Alvi et al. 001.
inline constexpr kinematics::FourBarLengths kThesis{60.0, 25.0, 70.0, 45.0};
inline constexpr kinematics::FourBarLengths kAlvi{80.0, 20.0, 66.0, 56.0};

/// Catch's Approx with an absolute margin only. Approx's default relative epsilon (~1.2e-5)
/// would otherwise silently widen every tolerance we state.
inline Approx within(double expected, double margin) { return Approx(expected).epsilon(0.0).margin(margin); }

/// a − b folded into [−π, π]: compares angles across the ±180° seam.
inline double angleDifference(double a, double b) { return std::remainder(a - b, 2.0 * kinematics::kPi); }

/// "column[i][j]" of the first NaN or infinity in any column of `r`, or "" if all are finite.
inline std::string firstNonFinite(const kinematics::SweepResult& r) {
  auto scan = [](const auto& columns, const char* name) -> std::string {
    for (std::size_t i = 0; i < columns.size(); ++i)
      for (std::size_t j = 0; j < columns[i].size(); ++j) {
        bool finite = true;
        if constexpr (std::is_same_v<std::decay_t<decltype(columns[i][j])>, double>)
          finite = std::isfinite(columns[i][j]);
        else finite = columns[i][j].allFinite();
        if (!finite) return std::string(name) + "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      }
    return {};
  };
  for (std::size_t j = 0; j < r.inputAngle.size(); ++j)
    if (!std::isfinite(r.inputAngle[j])) return "inputAngle[" + std::to_string(j) + "]";
  for (std::string s :
       {scan(r.position, "position"), scan(r.velocity, "velocity"), scan(r.acceleration, "acceleration"),
        scan(r.linkAngle, "linkAngle"), scan(r.linkOmega, "linkOmega"), scan(r.linkAlpha, "linkAlpha"),
        scan(r.transmissionAngle, "transmissionAngle")})
    if (!s.empty()) return s;
  return {};
}

/// A central-difference estimate of a derivative and how far the exact value may be from it.
struct Estimate {
  double value = 0.0;
  double tolerance = 0.0;
};

/// First and second time derivatives at t = 0 from samples q(kh), k = −2..2.
///
/// Where the tolerance comes from: D1(h) = (q(h) − q(−h))/2h and D2(h) = (q(h) − 2q(0) +
/// q(−h))/h² are off by c·h² + O(h⁴) (c = q'''/6, q''''/12). The same formula at step 2h is off
/// by 4c·h², so |D(2h) − D(h)| ≈ 3|c|h² (Richardson): allowing that difference in full is three
/// times the estimated truncation error, room for the h⁴ term. Each sample carries round-off up
/// to `noise`, which adds at most noise/h to D1 and 4·noise/h² to D2; we add twice that, because
/// D(2h) − D(h) carries round-off too.
inline std::array<Estimate, 2> differentiate(const std::array<double, 5>& q, double h, double noise) {
  const double d1 = (q[3] - q[1]) / (2.0 * h);
  const double d1Wide = (q[4] - q[0]) / (4.0 * h);
  const double d2 = (q[3] - 2.0 * q[2] + q[1]) / (h * h);
  const double d2Wide = (q[4] - 2.0 * q[2] + q[0]) / (4.0 * h * h);
  return {Estimate{d1, std::abs(d1Wide - d1) + 2.0 * noise / h},
          Estimate{d2, std::abs(d2Wide - d2) + 8.0 * noise / (h * h)}};
}

/// Positions of a mechanism at t = −2h..2h, the crank moving as θ(t) = θ0 + ωt + αt²/2 (so its
/// rate is ω + αt and its acceleration α, the state solvePose is given at t = 0), each solved
/// for positions only on the mechanism's own branch.
class TimeStencil {
public:
  TimeStencil(const kinematics::Mechanism& mechanism, const kinematics::DriverState& state, double h) : m_h(h) {
    for (int k = -2; k <= 2; ++k) {
      const double t = k * h;
      const double angle = state.position + state.velocity * t + 0.5 * state.acceleration * t * t;
      const auto pose = kinematics::solvePose(mechanism, {angle, 0.0, 0.0}, {false, false});
      INFO("stencil sample t = " << t << ": " << (pose.ok() ? std::string() : pose.error().message));
      REQUIRE(pose.ok());
      m_poses[static_cast<std::size_t>(k + 2)] = *pose;
    }
  }

  /// d/dt and d²/dt² of one coordinate (0: x, 1: y) of a point; `noise` in length units.
  std::array<Estimate, 2> point(kinematics::PointId id, int axis, double noise) const {
    std::array<double, 5> q{};
    for (std::size_t k = 0; k < 5; ++k) q[k] = m_poses[k].position[id.index][axis];
    return differentiate(q, m_h, noise);
  }

  /// d/dt and d²/dt² of a link's angle (unwrapped about t = 0); `noise` in radians.
  std::array<Estimate, 2> link(kinematics::LinkId id, double noise) const {
    std::array<double, 5> q{};
    const double centre = m_poses[2].linkAngle[id.index];
    for (std::size_t k = 0; k < 5; ++k) q[k] = centre + angleDifference(m_poses[k].linkAngle[id.index], centre);
    return differentiate(q, m_h, noise);
  }

private:
  double m_h;
  std::array<kinematics::Pose, 5> m_poses;
};

/// CHECKs that `exact` lies within an estimate's tolerance, printing both on failure.
inline void checkRate(double exact, const Estimate& estimate, const std::string& what) {
  INFO(std::setprecision(17) << what << ": exact " << exact << ", difference estimate " << estimate.value << " ± "
                             << estimate.tolerance);
  CHECK(std::abs(exact - estimate.value) <= estimate.tolerance);
}

/// CHECKs every moving point's velocity and acceleration and every link's ω and α of
/// `mechanism` at `state` against central time differences of its positions. `size` is the
/// linkage's extent: position round-off is taken as 64ε·size/`sine` (sine: the worst
/// transmission sine, which amplifies it), a link angle's as that over the link's length.
inline void checkAllRatesAgainstDifferences(const kinematics::Mechanism& mechanism,
                                            const kinematics::DriverState& state, double size, double sine = 0.2) {
  const auto pose = kinematics::solvePose(mechanism, state);
  INFO((pose.ok() ? std::string() : pose.error().message));
  REQUIRE(pose.ok());
  const double h = 1e-3 / (std::abs(state.velocity) + std::sqrt(std::abs(state.acceleration)));
  const TimeStencil stencil(mechanism, state, h);
  const double noise = 64.0 * std::numeric_limits<double>::epsilon() * size / sine;
  for (std::size_t i = 0; i < mechanism.points.size(); ++i) {
    if (std::holds_alternative<kinematics::GroundPoint>(mechanism.points[i].definition)) continue;
    for (int axis = 0; axis < 2; ++axis) {
      const auto d = stencil.point(kinematics::PointId{i}, axis, noise);
      const std::string what = mechanism.points[i].name + (axis == 0 ? ".x" : ".y");
      checkRate(pose->velocity[i][axis], d[0], "velocity of " + what);
      checkRate(pose->acceleration[i][axis], d[1], "acceleration of " + what);
    }
  }
  for (std::size_t k = 0; k < mechanism.links.size(); ++k) {
    const kinematics::Link& l = mechanism.links[k];
    const double length = (pose->position[l.second.index] - pose->position[l.first.index]).norm();
    const auto d = stencil.link(kinematics::LinkId{k}, 2.0 * noise / length);
    checkRate(pose->linkOmega[k], d[0], "omega of " + l.name);
    checkRate(pose->linkAlpha[k], d[1], "alpha of " + l.name);
  }
}

}  // namespace linkwright::test
