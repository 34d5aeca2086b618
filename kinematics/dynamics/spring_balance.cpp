#include "kinematics/dynamics/spring_balance.h"

#include "kinematics/dynamics/crank_terms.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

SpringFit fitSpring(const std::vector<double>& angle, const std::vector<double>& t0, const std::vector<double>& length,
                    const std::vector<double>& slope) {
  // J(k, c) = ∮ (T0 + k a + c b)² dθ with a = L L', b = −L': least where both derivatives vanish,
  //   k ∮a² + c ∮ab = −∮a T0,   k ∮ab + c ∮b² = −∮b T0,
  // and there J = ∮T0² + k ∮a T0 + c ∮b T0.
  const auto A = [&](std::size_t i) { return length[i] * slope[i]; };
  const auto B = [&](std::size_t i) { return -slope[i]; };
  const double aa = turnIntegral(angle, [&](std::size_t i) { return A(i) * A(i); });
  const double bb = turnIntegral(angle, [&](std::size_t i) { return B(i) * B(i); });
  const double ab = turnIntegral(angle, [&](std::size_t i) { return A(i) * B(i); });
  const double at0 = turnIntegral(angle, [&](std::size_t i) { return A(i) * t0[i]; });
  const double bt0 = turnIntegral(angle, [&](std::size_t i) { return B(i) * t0[i]; });
  const double t0t0 = turnIntegral(angle, [&](std::size_t i) { return t0[i] * t0[i]; });
  const double det = aa * bb - ab * ab;
  SpringFit fit;
  if (!(det > 1e-14 * aa * bb) || aa == 0.0) return fit;
  fit.sized = true;
  fit.stiffness = (-at0 * bb + bt0 * ab) / det;
  fit.pull = (-bt0 * aa + at0 * ab) / det;
  const double span = std::abs(angle.back() - angle.front());
  fit.rms = std::sqrt(std::max(0.0, t0t0 + fit.stiffness * at0 + fit.pull * bt0) / span);
  return fit;
}

double rmsOverTurn(const std::vector<double>& angle, const std::vector<double>& torque) {
  return std::sqrt(turnMean(angle, [&](std::size_t i) { return torque[i] * torque[i]; }));
}

Result<SpringBalance> balanceBySpring(const Mechanism& m, const LinkageDynamics& d, const SweepSpec& turn,
                                      const SpringEnd& first, const SpringEnd& second, const std::string& name) {
  if (auto e = checkCrankTurn(m, turn)) return *e;
  LinkageDynamics probe = d;  // the ends checked as a spring of the design would be
  probe.loads.springs.push_back({name, first, second, 0.0, 0.0, 0.0});
  if (auto e = checkDynamics(m, probe)) return *e;
  const double metres = *metresPerLengthUnit(m.lengthUnit);
  const auto moving = turnForces(m, d, turn, turn.omega, 0.0);
  if (!moving) return moving.error();
  const SweepResult& s = moving->kinematics;
  const PointId a = *m.findPoint(first.point), b = *m.findPoint(second.point);

  // L and L' = dL/dθ (m, m/rad) at each sample, from its positions and velocities per unit rate.
  std::vector<double> length(s.size()), slope(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    const Eigen::Vector2d between = metres * (s.position[b.index][j] - s.position[a.index][j]);
    const Eigen::Vector2d rate = metres * (s.velocity[b.index][j] - s.velocity[a.index][j]) / turn.omega;
    length[j] = between.norm();
    slope[j] = length[j] > 0.0 ? between.dot(rate) / length[j] : 0.0;
  }
  const std::vector<double>& t0 = moving->forces.driveTorque;
  std::vector<double> angle(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) angle[j] = s.inputAngle[j];
  const SpringFit fit = fitSpring(angle, t0, length, slope);
  if (!fit.sized)
    return Error{ErrorCode::InvalidValue, "spring",
                 "a spring from " + first.point + " to " + second.point +
                     " cannot change the driving torque enough to be sized (its length barely changes over the turn)"};
  const double k = fit.stiffness, c = fit.pull;
  if (!(k > 0.0))
    return Error{ErrorCode::InvalidValue, "spring",
                 "no spring from " + first.point + " to " + second.point + " lowers the RMS driving torque"};

  SpringBalance r;
  const double freeLength = c / k;  // m
  r.spring = {name, first, second, k, freeLength >= 0.0 ? freeLength / metres : 0.0, freeLength >= 0.0 ? 0.0 : -c};
  r.balanced = d;
  r.balanced.loads.springs.push_back(r.spring);
  r.angle = angle;
  r.torqueBefore = t0;
  r.torqueAfter.resize(t0.size());
  for (std::size_t j = 0; j < t0.size(); ++j) r.torqueAfter[j] = t0[j] + (k * length[j] - c) * slope[j];
  r.rmsBefore = rmsOverTurn(angle, r.torqueBefore);
  r.rmsAfter = rmsOverTurn(angle, r.torqueAfter);
  return r;
}

}  // namespace linkwright::kinematics
