#include "kinematics/synthesis/freudenstein.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <Eigen/Dense>

#include <cmath>

namespace linkwright::kinematics {
namespace {

Error pointsError(const std::string& message) { return Error{ErrorCode::InvalidValue, "points", message}; }

}  // namespace

Result<FreudensteinCoefficients> freudensteinCoefficients(std::span<const AnglePair> pairs) {
  if (pairs.size() < 3) return pointsError("points must number at least 3 (got " + std::to_string(pairs.size()) + ")");
  const auto n = static_cast<Eigen::Index>(pairs.size());
  Eigen::MatrixXd m(n, 3);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const AnglePair& p = pairs[static_cast<std::size_t>(i)];
    if (!std::isfinite(p.input) || !std::isfinite(p.output))
      return pointsError("points[" + std::to_string(i) + "] must have finite angles (got " + formatNumber(p.input) +
                         ", " + formatNumber(p.output) + ")");
    m(i, 0) = std::cos(p.output);
    m(i, 1) = -std::cos(p.input);
    m(i, 2) = 1.0;
    rhs(i) = std::cos(p.input - p.output);
  }
  // Column-pivoted QR: exact for a square system, least squares otherwise, and it reports the
  // rank. The entries are cosines and 1, so an absolute threshold is meaningful.
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
  qr.setThreshold(1e-10);
  if (qr.rank() < 3)
    return pointsError(
        "the precision points do not determine the linkage (coincident points, or inputs or outputs "
        "with equal cosines): choose other points or ranges");
  const Eigen::Vector3d k = qr.solve(rhs);
  if (!k.allFinite()) return pointsError("the precision points do not determine the linkage");
  return FreudensteinCoefficients{k(0), k(1), k(2)};
}

double freudensteinResidual(const FreudensteinCoefficients& k, const AnglePair& p) {
  return k.k1 * std::cos(p.output) - k.k2 * std::cos(p.input) + k.k3 - std::cos(p.input - p.output);
}

Result<FreudensteinLinkage> freudensteinLinkage(const FreudensteinCoefficients& k, double frame) {
  if (auto e = checkLength(frame, "frame")) return *e;
  if (!(std::isfinite(k.k1) && std::isfinite(k.k2) && std::isfinite(k.k3) && k.k1 != 0.0 && k.k2 != 0.0))
    return pointsError("the precision points give no four-bar (K1 = " + formatNumber(k.k1) +
                       ", K2 = " + formatNumber(k.k2) + "): choose other points or ranges");
  const double a = frame / k.k1, c = frame / k.k2;
  const double b2 = a * a + c * c + frame * frame - 2.0 * a * c * k.k3;
  if (!(b2 > 0.0))
    return pointsError("the precision points give no real coupler (b² = " + formatNumber(b2) +
                       "): choose other points or ranges");
  FreudensteinLinkage l;
  l.lengths = {frame, std::abs(a), std::sqrt(b2), std::abs(c)};
  l.crankReversed = a < 0.0;
  l.rockerReversed = c < 0.0;
  return l;
}

}  // namespace linkwright::kinematics
