#include "kinematics/analysis/coupler_curve.h"

#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

Eigen::Vector2d CurvePiece::at(double s) const {
  if (!cubic) return p0 + s * (p1 - p0);
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
}

Eigen::Vector2d CurvePiece::tangent(double s) const {
  if (!cubic) return p1 - p0;
  const double s2 = s * s;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  return d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1;
}

CurvePiece curvePiece(const CouplerCurve& curve, std::size_t i) {
  const std::size_t j = curve.next(i);
  CurvePiece piece;
  piece.p0 = curve.point[i];
  piece.p1 = curve.point[j];
  piece.theta0 = curve.crankAngle[i];
  piece.theta1 = curve.crankAngle[j];
  // The closing piece runs on to the first sample a turn of u later (and of θ on a full turn).
  const bool closing = curve.closed && j == 0;
  piece.du = curve.parameter[j] + (closing ? 2.0 * kPi : 0.0) - curve.parameter[i];
  if (closing && std::abs(piece.theta1 + 2.0 * kPi - piece.theta0 - piece.du) < 1e-9) piece.theta1 += 2.0 * kPi;
  piece.cubic = curve.rateOk[i] && curve.rateOk[j] && piece.du > 0.0;
  if (piece.cubic) {
    piece.m0 = piece.du * curve.derivative[i];
    piece.m1 = piece.du * curve.derivative[j];
  }
  return piece;
}

double curveSize(const CouplerCurve& curve) {
  if (curve.point.empty()) return 0.0;
  Eigen::Vector2d lo = curve.point.front(), hi = lo;
  for (const Eigen::Vector2d& p : curve.point) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

std::vector<Eigen::Vector2d> densified(const CouplerCurve& curve, std::size_t parts) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = curve.pieces();
  parts = std::max<std::size_t>(parts, 1);
  out.reserve(n * parts + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const CurvePiece piece = curvePiece(curve, i);
    for (std::size_t k = 0; k < parts; ++k)
      out.push_back(piece.at(static_cast<double>(k) / static_cast<double>(parts)));
  }
  if (!curve.closed && curve.size() > 0) out.push_back(curve.point.back());
  return out;
}

}  // namespace linkwright::kinematics
