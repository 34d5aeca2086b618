#include "kinematics/solve/newton_group.h"

#include "kinematics/model/validate.h"
#include "kinematics/solve/rrr_dyad.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::kinematics {
namespace {

constexpr int kMaxUnknowns = 2 * static_cast<int>(kMaxFreeGroupPoints);
// Dynamic sizes with a fixed capacity: the storage is inside the object, on the stack.
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxUnknowns, kMaxUnknowns>;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxUnknowns, 1>;
// Armijo's sufficient-decrease fraction: a step t must cut |Φ|² by at least 2σt of itself.
constexpr double kArmijo = 1e-4;

// The group's rows (its constraints, in the mechanism's order) and where its points' columns are.
class Group {
public:
  Group(const Mechanism& m, std::size_t first, std::size_t last) : m_first(first), m_last(last) {
    for (const DistanceConstraint& c : m.constraints) {
      const std::size_t later = constraintLaterPoint(c).index;
      if (later >= first && later < last && m_rows < kMaxUnknowns) m_row[static_cast<std::size_t>(m_rows++)] = &c;
    }
  }

  int unknowns() const { return 2 * static_cast<int>(m_last - m_first); }
  int rows() const { return m_rows; }
  const DistanceConstraint& row(int r) const { return *m_row[static_cast<std::size_t>(r)]; }
  bool inGroup(PointId p) const { return p.index >= m_first; }  // constraints never reach past the group
  Eigen::Index column(PointId p) const { return static_cast<Eigen::Index>(2 * (p.index - m_first)); }

  // The scale the tolerance is relative to: the longest constraint, or the farthest solved
  // point from the origin (round-off in positions grows with it).
  double size(const Pose& pose) const {
    double s = 0.0;
    for (int r = 0; r < m_rows; ++r) {
      const DistanceConstraint& c = row(r);
      s = std::max(s, c.length);
      for (const PointId p : {c.first, c.second})
        if (!inGroup(p)) s = std::max(s, pose.position[p.index].norm());
    }
    return s;
  }

  void load(const Pose& pose, Vector& q) const {
    for (std::size_t i = m_first; i < m_last; ++i) q.segment<2>(column(PointId{i})) = pose.position[i];
  }
  void store(const Vector& q, Pose& pose) const {
    for (std::size_t i = m_first; i < m_last; ++i) pose.position[i] = q.segment<2>(column(PointId{i}));
  }

  void residual(const Pose& pose, Vector& phi) const {
    for (int r = 0; r < m_rows; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d d = pose.position[c.first.index] - pose.position[c.second.index];
      phi[r] = (d.squaredNorm() - c.length * c.length) / (2.0 * c.length);
    }
  }

  void jacobian(const Pose& pose, Matrix& j) const {
    j.setZero();
    for (int r = 0; r < m_rows; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d g = (pose.position[c.first.index] - pose.position[c.second.index]) / c.length;
      if (inGroup(c.first)) j.block<1, 2>(r, column(c.first)) += g.transpose();
      if (inGroup(c.second)) j.block<1, 2>(r, column(c.second)) -= g.transpose();
    }
  }

  // −J_k ẋ_k for the solved points' rates `rate` (velocity or acceleration), plus −J̇q̇ when
  // `velocity` is given (the acceleration system).
  void rateRhs(const Pose& pose, const std::vector<Eigen::Vector2d>& rate, const std::vector<Eigen::Vector2d>* velocity,
               Vector& rhs) const {
    for (int r = 0; r < m_rows; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d d = pose.position[c.first.index] - pose.position[c.second.index];
      double b = 0.0;
      if (!inGroup(c.first)) b -= d.dot(rate[c.first.index]);
      if (!inGroup(c.second)) b += d.dot(rate[c.second.index]);
      if (velocity != nullptr) b -= ((*velocity)[c.first.index] - (*velocity)[c.second.index]).squaredNorm();
      rhs[r] = b / c.length;
    }
  }

  void storeRates(const Vector& x, std::vector<Eigen::Vector2d>& rate) const {
    for (std::size_t i = m_first; i < m_last; ++i) rate[i] = x.segment<2>(column(PointId{i}));
  }

private:
  std::size_t m_first;
  std::size_t m_last;
  std::array<const DistanceConstraint*, kMaxUnknowns> m_row{};
  int m_rows = 0;
};

// One damped Newton step from q (whose residual is phi); on success q, phi and the pose hold
// the new point. False if no step length reduces |Φ|² enough: the pose is left at q.
bool newtonStep(const Group& g, const Eigen::PartialPivLU<Matrix>& lu, double size, Vector& q, Vector& phi,
                Vector& trial, Pose& pose) {
  const Vector step = lu.solve(-phi);
  if (!step.allFinite()) return false;
  const double f0 = phi.squaredNorm();
  const double longest = step.cwiseAbs().maxCoeff();
  double t = longest > size ? size / longest : 1.0;
  for (int h = 0; h <= kNewtonHalvings; ++h, t *= 0.5) {
    trial = q + t * step;
    g.store(trial, pose);
    g.residual(pose, phi);
    if (phi.squaredNorm() <= (1.0 - 2.0 * kArmijo * t) * f0) {
      q = trial;
      return true;
    }
  }
  g.store(q, pose);
  g.residual(pose, phi);
  return false;
}

}  // namespace

NewtonOutcome solveFreeGroup(const Mechanism& m, std::size_t first, std::size_t last, const NewtonSettings& settings,
                             bool velocities, bool accelerations, Pose& pose) {
  const Group g(m, first, last);
  const Eigen::Index n = g.unknowns();
  Vector q(n), phi(n), trial(n);
  Matrix j(n, n);
  Eigen::PartialPivLU<Matrix> lu(n);
  const double size = g.size(pose);
  const double target = settings.tolerance * size;
  g.load(pose, q);
  g.residual(pose, phi);
  NewtonOutcome out;
  // Written as a negation so that a NaN residual never counts as converged.
  while (!(phi.cwiseAbs().maxCoeff() <= target)) {
    if (out.iterations >= settings.maxIterations) break;
    ++out.iterations;
    g.jacobian(pose, j);
    lu.compute(j);
    if (!newtonStep(g, lu, size, q, phi, trial, pose)) break;
  }
  out.residual = phi.cwiseAbs().maxCoeff();
  if (!(out.residual <= target)) {
    out.status = NewtonStatus::NoConvergence;
    return out;
  }
  if (!velocities && !accelerations) return out;
  g.jacobian(pose, j);
  lu.compute(j);
  if (!(lu.rcond() > kSingularSine)) {
    out.status = NewtonStatus::Singular;
    return out;
  }
  g.rateRhs(pose, pose.velocity, nullptr, trial);
  q = lu.solve(trial);
  g.storeRates(q, pose.velocity);
  if (!accelerations) return out;
  g.rateRhs(pose, pose.acceleration, &pose.velocity, trial);
  q = lu.solve(trial);
  g.storeRates(q, pose.acceleration);
  return out;
}

double constraintMisfit(const DistanceConstraint& c, const Pose& pose) {
  return (pose.position[c.first.index] - pose.position[c.second.index]).norm() - c.length;
}

std::optional<Error> checkNewtonSettings(const NewtonSettings& s) {
  if (!(s.tolerance >= 1e-15 && s.tolerance < 1.0))
    return Error{ErrorCode::InvalidValue, "newton.tolerance",
                 "newton.tolerance must be at least 1e-15 and below 1 (got " + formatNumber(s.tolerance) + ")"};
  if (s.maxIterations < 1 || s.maxIterations > 1000)
    return Error{ErrorCode::InvalidValue, "newton.maxIterations",
                 "newton.maxIterations must be from 1 to 1000 (got " + std::to_string(s.maxIterations) + ")"};
  return std::nullopt;
}

}  // namespace linkwright::kinematics
