#pragma once
// The least-squares model behind path generation (path_generation.h): the parameter vector,
// its bounded maps to lengths and coupler-point offsets, the coupler point of a four-bar held on
// one branch, and the residual functor Eigen's Levenberg–Marquardt minimises. Everything here
// is in normalised units: the targets moved to their bounding box's centre and divided by its
// diagonal, so every unknown is of order one and one set of tolerances fits every task.
// Internal to path generation; not part of the core's public API.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/vec2.h"
#include "kinematics/synthesis/path_generation.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace linkwright::kinematics::path_model {

inline constexpr double kLengthMin = 1e-2;  ///< shortest link, × scale (the header's bound)
inline constexpr double kLengthMax = 10.0;  ///< longest link, × scale
inline constexpr double kOffsetMax = 10.0;  ///< largest |along| and |across| of P, × scale
/// Weight of the assembly penalty against the distances: a gap of 1 % of the scale costs as
/// much as missing a target by 10 %, so LM leaves unassemblable angles first.
inline constexpr double kPenaltyWeight = 10.0;

/// Where each unknown sits in the parameter vector.
enum Slot : int { kO2x, kO2y, kBeta, kFrame, kCrank, kCoupler, kRocker, kAlong, kAcross, kAngles };

/// A four-bar with its coupler point, placed in the plane (normalised units).
struct Linkage {
  Eigen::Vector2d o2 = Eigen::Vector2d::Zero();
  double beta = 0.0;  ///< frame angle, O2→O4 (rad)
  double frame = 1.0, crank = 1.0, coupler = 1.0, rocker = 1.0;
  double along = 0.0, across = 0.0;
  Eigen::Vector2d o4() const { return o2 + frame * Eigen::Vector2d(std::cos(beta), std::sin(beta)); }
};

/// How the crank angles are parametrised.
struct Timing {
  std::optional<TimingReference> reference;  ///< none: one free angle per target
  std::vector<double> tau;                   ///< the prescribed angles (rad), if any
};

inline double logistic(double u) { return 1.0 / (1.0 + std::exp(-u)); }

/// The bounded length for parameter u: kLengthMin·(kLengthMax/kLengthMin)^σ(u).
inline double lengthOf(double u) { return kLengthMin * std::pow(kLengthMax / kLengthMin, logistic(u)); }

/// The parameter of a length, the length first brought just inside the bounds.
inline double lengthParameter(double length) {
  const double span = std::log(kLengthMax / kLengthMin);
  const double s = std::clamp(std::log(length / kLengthMin) / span, 1e-6, 1.0 - 1e-6);
  return std::log(s / (1.0 - s));
}

/// The bounded offset for parameter v: kOffsetMax·tanh(v/kOffsetMax) (≈ v for |v| ≪ kOffsetMax).
inline double offsetOf(double v) { return kOffsetMax * std::tanh(v / kOffsetMax); }

inline double offsetParameter(double offset) {
  return kOffsetMax * std::atanh(std::clamp(offset / kOffsetMax, -1.0 + 1e-9, 1.0 - 1e-9));
}

/// Unknowns: the linkage's nine, plus one angle per target (no timing), one start angle
/// (timing from a free start), or none (timing from the frame line).
inline int parameterCount(const Timing& t, int targets) {
  if (!t.reference) return kAngles + targets;
  return *t.reference == TimingReference::Start ? kAngles + 1 : kAngles;
}

inline Linkage decode(const Eigen::VectorXd& x) {
  Linkage l;
  l.o2 = {x[kO2x], x[kO2y]};
  l.beta = x[kBeta];
  l.frame = lengthOf(x[kFrame]);
  l.crank = lengthOf(x[kCrank]);
  l.coupler = lengthOf(x[kCoupler]);
  l.rocker = lengthOf(x[kRocker]);
  l.along = offsetOf(x[kAlong]);
  l.across = offsetOf(x[kAcross]);
  return l;
}

/// Writes the linkage's nine slots of x.
inline void encode(const Linkage& l, Eigen::VectorXd& x) {
  x[kO2x] = l.o2.x();
  x[kO2y] = l.o2.y();
  x[kBeta] = l.beta;
  x[kFrame] = lengthParameter(l.frame);
  x[kCrank] = lengthParameter(l.crank);
  x[kCoupler] = lengthParameter(l.coupler);
  x[kRocker] = lengthParameter(l.rocker);
  x[kAlong] = offsetParameter(l.along);
  x[kAcross] = offsetParameter(l.across);
}

/// The crank's absolute angle at target i (rad).
inline double crankAngle(const Eigen::VectorXd& x, const Timing& t, std::size_t i) {
  if (!t.reference) return x[kAngles + static_cast<Eigen::Index>(i)];
  return (*t.reference == TimingReference::Start ? x[kAngles] : x[kBeta]) + t.tau[i];
}

/// The coupler point at crank angle theta, and how far the dyad is from assembling (0 when it
/// assembles). Past a limit the dyad is clamped to it, so the point moves continuously.
struct CouplerPosition {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double gap = 0.0;
};

inline CouplerPosition couplerPosition(const Linkage& l, const Eigen::Vector2d& o4, double theta, Branch branch) {
  const Eigen::Vector2d b = l.o2 + l.crank * Eigen::Vector2d(std::cos(theta), std::sin(theta));
  const Eigen::Vector2d d = o4 - b;
  const double distance = std::max(d.norm(), 1e-12);
  const Eigen::Vector2d u = d / distance;
  CouplerPosition out;
  out.gap = std::max({0.0, distance - (l.coupler + l.rocker), std::abs(l.coupler - l.rocker) - distance});
  // rrr_dyad.h's construction with P1 = B (coupler), P2 = O4 (rocker), s = +1 on Open.
  const double foot = std::clamp(0.5 * (l.coupler * l.coupler - l.rocker * l.rocker + distance * distance) / distance,
                                 -l.coupler, l.coupler);
  const double h = std::sqrt(std::max(0.0, l.coupler * l.coupler - foot * foot));
  const double s = branch == Branch::Open ? 1.0 : -1.0;
  const Eigen::Vector2d c = b + foot * u + s * h * perp(u);
  const Eigen::Vector2d along = (c - b) / l.coupler;
  out.point = b + l.along * along + l.across * perp(along);
  return out;
}

/// The residuals for Eigen's LevenbergMarquardt: per target, P − target (two) and the weighted
/// assembly gap (one); zeros after them when there are fewer residuals than unknowns (MINPACK
/// asks for at least as many). The Jacobian is by forward differences: the residual is cheap
/// (one dyad per target) and at most 19 unknowns.
struct Residual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  using QRSolver = Eigen::ColPivHouseholderQR<JacobianType>;

  const std::vector<Eigen::Vector2d>* targets = nullptr;
  const Timing* timing = nullptr;
  Branch branch = Branch::Open;

  int inputs() const { return parameterCount(*timing, static_cast<int>(targets->size())); }
  int values() const { return std::max(3 * static_cast<int>(targets->size()), inputs()); }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const Linkage l = decode(x);
    const Eigen::Vector2d o4 = l.o4();
    f.setZero(values());
    for (std::size_t i = 0; i < targets->size(); ++i) {
      const CouplerPosition p = couplerPosition(l, o4, crankAngle(x, *timing, i), branch);
      const auto row = static_cast<Eigen::Index>(3 * i);
      f[row] = p.point.x() - (*targets)[i].x();
      f[row + 1] = p.point.y() - (*targets)[i].y();
      f[row + 2] = kPenaltyWeight * p.gap;
    }
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian) const {
    Eigen::VectorXd f0, f1;
    (*this)(x, f0);
    Eigen::VectorXd probe = x;
    for (Eigen::Index j = 0; j < x.size(); ++j) {
      // √ε relative step: the usual forward-difference balance of truncation and round-off.
      const double step = 1.5e-8 * std::max(1.0, std::abs(x[j]));
      probe[j] = x[j] + step;
      (*this)(probe, f1);
      jacobian.col(j) = (f1 - f0) / step;
      probe[j] = x[j];
    }
    return 0;
  }
};

}  // namespace linkwright::kinematics::path_model
