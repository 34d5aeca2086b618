#include "kinematics/solve/newton_group.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/rrr_dyad.h"
#include "kinematics/solve/small_lu.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// Armijo's sufficient-decrease fraction: a step t must cut |Φ|² by at least 2σt of itself.
constexpr double kArmijo = 1e-4;

template <int N>
using Vector = Eigen::Matrix<double, N, 1>;

// The group's rows (its constraints, in the mechanism's order) and where its points' columns
// are. N = 2k unknowns, and as many rows (checkMechanism).
template <int N>
class Group {
public:
  Group(const Mechanism& m, std::size_t first) : m_first(first) {
    int rows = 0;
    for (const DistanceConstraint& c : m.constraints) {
      const std::size_t later = constraintLaterPoint(c).index;
      if (later >= first && later < first + N / 2 && rows < N) m_row[rows++] = &c;
    }
  }

  const DistanceConstraint& row(int r) const { return *m_row[r]; }
  bool inGroup(PointId p) const { return p.index >= m_first; }  // constraints never reach past the group
  int column(PointId p) const { return 2 * static_cast<int>(p.index - m_first); }

  // The scale the tolerance is relative to: the longest constraint, or the farthest solved
  // point from the origin (round-off in positions grows with it).
  double size(const Pose& pose) const {
    double s = 0.0;
    for (int r = 0; r < N; ++r) {
      const DistanceConstraint& c = row(r);
      s = std::max(s, c.length);
      for (const PointId p : {c.first, c.second})
        if (!inGroup(p)) s = std::max(s, pose.position[p.index].norm());
    }
    return s;
  }

  void load(const Pose& pose, Vector<N>& q) const {
    for (int i = 0; i < N / 2; ++i) q.template segment<2>(2 * i) = pose.position[m_first + i];
  }
  void store(const Vector<N>& q, Pose& pose) const {
    for (int i = 0; i < N / 2; ++i) pose.position[m_first + i] = q.template segment<2>(2 * i);
  }

  void residual(const Pose& pose, Vector<N>& phi) const {
    for (int r = 0; r < N; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d d = pose.position[c.first.index] - pose.position[c.second.index];
      phi[r] = (d.squaredNorm() - c.length * c.length) / (2.0 * c.length);
    }
  }

  // Into `j`, unfactorized.
  void jacobian(const Pose& pose, SmallLu<N>& j) const {
    j.setZero();
    for (int r = 0; r < N; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d g = (pose.position[c.first.index] - pose.position[c.second.index]) / c.length;
      if (inGroup(c.first)) {
        j.at(r, column(c.first)) += g.x();
        j.at(r, column(c.first) + 1) += g.y();
      }
      if (inGroup(c.second)) {
        j.at(r, column(c.second)) -= g.x();
        j.at(r, column(c.second) + 1) -= g.y();
      }
    }
  }

  // −J_k ẋ_k for the solved points' rates `rate` (velocity or acceleration), plus −J̇q̇ when
  // `velocity` is given (the acceleration system).
  void rateRhs(const Pose& pose, const std::vector<Eigen::Vector2d>& rate, const std::vector<Eigen::Vector2d>* velocity,
               Vector<N>& rhs) const {
    for (int r = 0; r < N; ++r) {
      const DistanceConstraint& c = row(r);
      const Eigen::Vector2d d = pose.position[c.first.index] - pose.position[c.second.index];
      double b = 0.0;
      if (!inGroup(c.first)) b -= d.dot(rate[c.first.index]);
      if (!inGroup(c.second)) b += d.dot(rate[c.second.index]);
      if (velocity != nullptr) b -= ((*velocity)[c.first.index] - (*velocity)[c.second.index]).squaredNorm();
      rhs[r] = b / c.length;
    }
  }

  void storeRates(const Vector<N>& x, std::vector<Eigen::Vector2d>& rate) const {
    for (int i = 0; i < N / 2; ++i) rate[m_first + i] = x.template segment<2>(2 * i);
  }

private:
  std::size_t m_first;
  std::array<const DistanceConstraint*, N> m_row{};
};

// One damped Newton step from q (whose residual is phi); on success q, phi and the pose hold
// the new point. False if no step length reduces |Φ|² enough: the pose is left at q.
template <int N>
bool newtonStep(const Group<N>& g, const SmallLu<N>& lu, double size, Vector<N>& q, Vector<N>& phi, Pose& pose) {
  Vector<N> step = -phi;
  lu.solve(step.data());
  if (!step.allFinite()) return false;
  const double f0 = phi.squaredNorm();
  const double longest = step.cwiseAbs().maxCoeff();
  double t = longest > size ? size / longest : 1.0;
  for (int h = 0; h <= kNewtonHalvings; ++h, t *= 0.5) {
    const Vector<N> trial = q + t * step;
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

// solveFreeGroup for a group of N unknowns: the size is a constant in every loop.
template <int N>
NewtonOutcome solveGroup(const Mechanism& m, std::size_t first, const NewtonSettings& settings, bool velocities,
                         bool accelerations, Pose& pose) {
  const Group<N> g(m, first);
  Vector<N> q;
  Vector<N> phi;
  SmallLu<N> lu;
  const double size = g.size(pose);
  const double target = settings.tolerance * size;
  g.load(pose, q);
  g.residual(pose, phi);
  NewtonOutcome out;
  // Written as a negation so that a NaN residual never counts as converged.
  while (!(phi.cwiseAbs().maxCoeff() <= target)) {
    if (out.iterations >= settings.maxIterations) break;
    ++out.iterations;
    g.jacobian(pose, lu);
    lu.compute();
    if (!newtonStep(g, lu, size, q, phi, pose)) break;
  }
  out.residual = phi.cwiseAbs().maxCoeff();
  if (!(out.residual <= target)) {
    out.status = NewtonStatus::NoConvergence;
    return out;
  }
  if (!velocities && !accelerations) return out;
  g.jacobian(pose, lu);
  lu.compute();
  if (!lu.rcondAbove(kSingularSine)) {
    out.status = NewtonStatus::Singular;
    return out;
  }
  Vector<N> rate;
  g.rateRhs(pose, pose.velocity, nullptr, rate);
  lu.solve(rate.data());
  g.storeRates(rate, pose.velocity);
  if (!accelerations) return out;
  g.rateRhs(pose, pose.acceleration, &pose.velocity, rate);
  lu.solve(rate.data());
  g.storeRates(rate, pose.acceleration);
  return out;
}

}  // namespace

NewtonOutcome solveFreeGroup(const Mechanism& m, std::size_t first, std::size_t last, const NewtonSettings& settings,
                             bool velocities, bool accelerations, Pose& pose) {
  static_assert(kMaxFreeGroupPoints == 8, "one case below per group size");
  const bool v = velocities;
  const bool a = accelerations;
  switch (last - first) {
  case 1: return solveGroup<2>(m, first, settings, v, a, pose);
  case 2: return solveGroup<4>(m, first, settings, v, a, pose);
  case 3: return solveGroup<6>(m, first, settings, v, a, pose);
  case 4: return solveGroup<8>(m, first, settings, v, a, pose);
  case 5: return solveGroup<10>(m, first, settings, v, a, pose);
  case 6: return solveGroup<12>(m, first, settings, v, a, pose);
  case 7: return solveGroup<14>(m, first, settings, v, a, pose);
  case 8: return solveGroup<16>(m, first, settings, v, a, pose);
  default: return {NewtonStatus::NoConvergence, 0, 0.0};  // checkMechanism rules it out
  }
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
