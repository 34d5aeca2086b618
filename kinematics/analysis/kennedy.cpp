#include "kinematics/analysis/kennedy.h"

#include "kinematics/model/vec2.h"

#include <cmath>
#include <optional>
#include <vector>

namespace linkwright::kinematics {
namespace {

bool known(const InstantCentre& c) { return c.kind == CentreKind::Finite || c.kind == CentreKind::AtInfinity; }

// A line through a point with a unit direction, or the line at infinity.
struct Line {
  bool atInfinity = false;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  std::size_t via = 0;  // the third body k whose centres Iik, Ijk it joins
};

std::optional<Line> lineThrough(const InstantCentre& a, const InstantCentre& b, double scale, std::size_t via) {
  const bool aFar = a.kind == CentreKind::AtInfinity, bFar = b.kind == CentreKind::AtInfinity;
  if (aFar && bFar) return Line{true, {}, {}, via};
  if (aFar) return Line{false, b.position, a.direction, via};
  if (bFar) return Line{false, a.position, b.direction, via};
  const Eigen::Vector2d d = b.position - a.position;
  if (d.norm() <= kCentreTolerance * scale) return std::nullopt;  // one point: no line
  return Line{false, a.position, d.normalized(), via};
}

// Where two lines meet, and how well: the sine of their angle (1 when one is at infinity:
// the meeting is exact), 0 when they are parallel or coincide.
struct Meeting {
  InstantCentre centre;
  double quality = 0.0;
};

Meeting meet(const Line& l1, const Line& l2, double scale) {
  const InstantCentre indeterminate{CentreKind::Indeterminate, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  if (l1.atInfinity && l2.atInfinity) return {indeterminate, 0.0};
  if (l1.atInfinity) return {centreAtInfinity(l2.direction), 1.0};
  if (l2.atInfinity) return {centreAtInfinity(l1.direction), 1.0};
  const double sine = cross(l1.direction, l2.direction);
  const Eigen::Vector2d offset = l2.point - l1.point;
  if (std::abs(sine) <= kCentreTolerance) {
    if (std::abs(cross(l1.direction, offset)) <= kCentreTolerance * scale) return {indeterminate, 0.0};
    return {centreAtInfinity(l1.direction), 0.0};
  }
  const Eigen::Vector2d at = l1.point + (cross(offset, l2.direction) / sine) * l1.direction;
  return {{CentreKind::Finite, at, Eigen::Vector2d::Zero()}, std::abs(sine)};
}

struct Located {
  std::size_t pair = 0;
  InstantCentre centre;
  CentreOrigin origin;
};

// The best meeting of the lines reaching Iij, if two lines do: the widest crossing; else
// parallel lines' point at infinity; else (all coincide) Indeterminate.
// `lines` is scratch space, kept between calls so a sweep does not allocate per centre.
std::optional<Located> locate(const InstantCentres& c, std::size_t i, std::size_t j, std::vector<Line>& lines) {
  lines.clear();
  for (std::size_t k = 1; k <= c.bodyCount(); ++k) {
    if (k == i || k == j) continue;
    const InstantCentre& ik = c.centre(i, k);
    const InstantCentre& jk = c.centre(j, k);
    if (!known(ik) || !known(jk)) continue;
    if (auto line = lineThrough(ik, jk, c.scale, k)) lines.push_back(*line);
  }
  std::optional<Located> best;
  double bestQuality = -1.0;
  const auto rank = [](const Meeting& m) {  // a determinate meeting beats any degenerate one
    return m.quality > kCentreTolerance ? m.quality : m.centre.kind == CentreKind::AtInfinity ? 0.0 : -0.5;
  };
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (std::size_t b = a + 1; b < lines.size(); ++b) {
      const Meeting m = meet(lines[a], lines[b], c.scale);
      if (rank(m) <= bestQuality) continue;
      bestQuality = rank(m);
      CentreOrigin origin;
      origin.rule = CentreRule::Kennedy;
      origin.via = {lines[a].via, lines[b].via};
      best = Located{c.pairIndex(i, j), m.centre, origin};
    }
  return best;
}

}  // namespace

InstantCentre centreAtInfinity(const Eigen::Vector2d& d) {
  if (!d.allFinite() || !(d.norm() > 0.0))
    return {CentreKind::Indeterminate, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  const Eigen::Vector2d unit = d.normalized();
  const bool canonical = unit.x() > 0.0 || (unit.x() == 0.0 && unit.y() > 0.0);
  return {CentreKind::AtInfinity, Eigen::Vector2d::Zero(), canonical ? unit : Eigen::Vector2d(-unit)};
}

void completeByKennedy(InstantCentres& c) {
  const std::size_t n = c.bodyCount();
  std::vector<Located> found, undecided;  // this pass's meetings, and its degenerate ones
  std::vector<Line> lines;
  found.reserve(c.centres.size());
  undecided.reserve(c.centres.size());
  lines.reserve(n);
  for (;;) {
    found.clear();
    undecided.clear();
    for (std::size_t i = 1; i <= n; ++i)
      for (std::size_t j = i + 1; j <= n; ++j) {
        if (c.centre(i, j).kind != CentreKind::Unresolved) continue;
        if (auto at = locate(c, i, j, lines)) (known(at->centre) ? found : undecided).push_back(*at);
      }
    if (found.empty()) break;
    for (const Located& l : found) {
      c.centres[l.pair] = l.centre;
      c.origins[l.pair] = l.origin;
    }
  }
  for (const Located& l : undecided) {
    c.centres[l.pair] = l.centre;
    c.origins[l.pair] = l.origin;
  }
}

}  // namespace linkwright::kinematics
