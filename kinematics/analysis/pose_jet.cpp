#include "kinematics/analysis/pose_jet.h"

#include "kinematics/model/constraint_form.h"
#include "kinematics/solve/solve_scope.h"

#include <Eigen/LU>

#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

namespace linkwright::kinematics {
namespace {

// A number of the mechanism as a jet: its value, and its derivative as the difference the
// stepped mechanism holds.
MotionJet number(double value, double stepped) { return MotionJet::dimension(value, stepped - value); }

JetVector vector(const Eigen::Vector2d& value, const Eigen::Vector2d& stepped) {
  return {number(value.x(), stepped.x()), number(value.y(), stepped.y())};
}

JetVector unit(const JetVector& v) { return reciprocal(norm(v)) * v; }

JetVector direction(const MotionJet& angle) { return {cos(angle), sin(angle)}; }

// The candidate nearer the solver's position.
const JetVector& nearer(const JetVector& a, const JetVector& b, const Eigen::Vector2d& target) {
  return (a.value() - target).squaredNorm() <= (b.value() - target).squaredNorm() ? a : b;
}

struct GuideJet {
  JetVector point;
  JetVector direction;
};

struct Differentiator {
  const Mechanism& m;
  const Mechanism& s;
  std::span<const Eigen::Vector2d> nominal;
  MotionJet input;
  PoseJet& out;

  const JetVector& at(PointId id) const { return out.position[id.index]; }

  // C at l1 from p1 and l2 from p2, on the side of the solver's C (rrr_dyad.h's closed form).
  std::optional<JetVector> rrr(const JetVector& p1, const MotionJet& l1, const JetVector& p2, const MotionJet& l2,
                               std::size_t i) const {
    const JetVector d = p2 - p1;
    const MotionJet L = norm(d);
    const MotionJet reach = l1 + l2 - L;
    const MotionJet inner = L - abs(l1 - l2);
    if (!(L.value() > 0.0) || !(reach.value() > 0.0) || !(inner.value() > 0.0)) return std::nullopt;
    const MotionJet inverse = reciprocal(L);
    const MotionJet h = 0.5 * sqrt(reach * (l1 + l2 + L) * inner * (L + abs(l1 - l2))) * inverse;
    const MotionJet a = 0.5 * (l1 * l1 - l2 * l2 + L * L) * inverse;
    const JetVector u = inverse * d;
    const JetVector foot = p1 + a * u;
    const JetVector n = perp(u);
    return nearer(foot + h * n, foot - h * n, nominal[i]);
  }

  GuideJet guide(const Guide& g, const Guide& gs) const {
    const JetVector point = vector(g.point, gs.point);
    const MotionJet angle = number(g.angle, gs.angle);
    if (!g.link) return {point, direction(angle)};
    const Link& l = m.links[g.link->index];
    const JetVector& a = at(l.first);
    const JetVector e = unit(at(l.second) - a);
    const MotionJet c = cos(angle), sn = sin(angle);
    return {a + point.x * e + point.y * perp(e), c * e + sn * perp(e)};
  }

  std::optional<JetVector> place(std::size_t, const GroundPoint& g, const GroundPoint& gs) const {
    return vector(g.position, gs.position);
  }
  std::optional<JetVector> place(std::size_t, const CrankPoint& c, const CrankPoint& cs) const {
    const MotionJet phi = input + number(c.phase, cs.phase);
    return at(c.pivot) + number(c.length, cs.length) * direction(phi);
  }
  std::optional<JetVector> place(std::size_t, const PathPoint& d, const PathPoint& ds) const {
    if (const auto* line = std::get_if<PolylinePath>(&d.path)) {
      const auto& steppedLine = std::get<PolylinePath>(ds.path);
      const auto& v = line->vertices;
      // The segment the solver's path_shape.h puts s on: the first before the start, the last
      // after the end.
      MotionJet along = input;
      std::size_t k = 0;
      for (; k + 2 < v.size(); ++k) {
        const MotionJet length =
            norm(vector(v[k + 1], steppedLine.vertices[k + 1]) - vector(v[k], steppedLine.vertices[k]));
        if (along.value() < length.value()) break;
        along -= length;
      }
      const JetVector start = vector(v[k], steppedLine.vertices[k]);
      return start + along * unit(vector(v[k + 1], steppedLine.vertices[k + 1]) - start);
    }
    const auto& arc = std::get<ArcPath>(d.path);
    const auto& steppedArc = std::get<ArcPath>(ds.path);
    const double turn = arc.sweep >= 0.0 ? 1.0 : -1.0;
    const MotionJet radius = number(arc.radius, steppedArc.radius);
    const MotionJet angle = number(arc.startAngle, steppedArc.startAngle) + turn * input / radius;
    return vector(arc.centre, steppedArc.centre) + radius * direction(angle);
  }
  std::optional<JetVector> place(std::size_t i, const ActuatorPoint& a, const ActuatorPoint& as) const {
    return rrr(at(a.first), number(a.length, as.length), at(a.base), input, i);
  }
  std::optional<JetVector> place(std::size_t i, const RrrPoint& r, const RrrPoint& rs) const {
    return rrr(at(r.first), number(r.firstLength, rs.firstLength), at(r.second),
               number(r.secondLength, rs.secondLength), i);
  }
  std::optional<JetVector> place(std::size_t i, const RrpPoint& p, const RrpPoint& ps) const {
    const GuideJet line = guide(p.guide, ps.guide);
    const JetVector d = line.point - at(p.first);
    const MotionJet b = dot(line.direction, d);
    const MotionJet distance = abs(cross(line.direction, d));
    const MotionJet length = number(p.length, ps.length);
    if (!(length.value() > distance.value())) return std::nullopt;
    const MotionJet root = sqrt((length - distance) * (length + distance));
    return nearer(line.point + (root - b) * line.direction, line.point - (root + b) * line.direction, nominal[i]);
  }
  std::optional<JetVector> place(std::size_t, const RprPoint& r, const RprPoint& rs) const {
    const JetVector rel = at(r.through) - at(r.pivot);
    if (!(dot(rel, rel).value() > 0.0)) return std::nullopt;
    return at(r.pivot) + number(r.length, rs.length) * unit(rel);
  }
  std::optional<JetVector> place(std::size_t, const PrpPoint& p, const PrpPoint& ps) const {
    const GuideJet l1 = guide(p.first, ps.first);
    const GuideJet l2 = guide(p.second, ps.second);
    const MotionJet sine = cross(l1.direction, l2.direction);
    if (!(std::abs(sine.value()) > 0.0)) return std::nullopt;
    return l1.point + (cross(l2.point - l1.point, l2.direction) / sine) * l1.direction;
  }
  std::optional<JetVector> place(std::size_t, const AttachedPoint& a, const AttachedPoint& as) const {
    const Link& l = m.links[a.link.index];
    const JetVector e = unit(at(l.second) - at(l.first));
    return at(l.first) + number(a.along, as.along) * e + number(a.across, as.across) * perp(e);
  }

  // The free points [first, last): Newton in jet arithmetic from the solver's positions,
  // with the real Jacobian there (see the header).
  bool freeGroup(std::size_t first, std::size_t last) {
    const auto n = static_cast<Eigen::Index>(2 * (last - first));
    for (std::size_t i = first; i < last; ++i) out.position[i] = {MotionJet(nominal[i].x()), MotionJet(nominal[i].y())};
    std::vector<std::size_t> rows;
    for (std::size_t c = 0; c < m.constraints.size(); ++c) {
      const std::size_t later = constraintLaterPoint(m.constraints[c]).index;
      if (later >= first && later < last) rows.push_back(c);
    }
    if (static_cast<Eigen::Index>(rows.size()) != n) return false;
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index r = 0; r < n; ++r) {
      const DistanceConstraint& c = m.constraints[rows[static_cast<std::size_t>(r)]];
      const Eigen::Vector2d d = nominal[c.first.index] - nominal[c.second.index];
      if (c.first.index >= first)
        jacobian.block<1, 2>(r, 2 * static_cast<Eigen::Index>(c.first.index - first)) += 2.0 * d;
      if (c.second.index >= first)
        jacobian.block<1, 2>(r, 2 * static_cast<Eigen::Index>(c.second.index - first)) -= 2.0 * d;
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(jacobian);
    if (!(std::abs(lu.determinant()) > 0.0)) return false;
    std::vector<MotionJet> residual(static_cast<std::size_t>(n));
    for (int iteration = 0; iteration < 5; ++iteration) {
      for (Eigen::Index r = 0; r < n; ++r) {
        const DistanceConstraint& c = m.constraints[rows[static_cast<std::size_t>(r)]];
        const DistanceConstraint& cs = s.constraints[rows[static_cast<std::size_t>(r)]];
        const JetVector d = at(c.first) - at(c.second);
        const MotionJet length = number(c.length, cs.length);
        residual[static_cast<std::size_t>(r)] = dot(d, d) - length * length;
      }
      // J₀ is real: each of the six coefficients of the step solves with it alone.
      Eigen::MatrixXd rhs(n, 6);
      for (Eigen::Index r = 0; r < n; ++r)
        for (Eigen::Index k = 0; k < 6; ++k)
          rhs(r, k) = residual[static_cast<std::size_t>(r)].coefficients()[static_cast<std::size_t>(k)];
      const Eigen::MatrixXd step = lu.solve(rhs);
      const auto delta = [&](std::size_t row) {
        std::array<double, 6> c{};
        for (std::size_t k = 0; k < 6; ++k) c[k] = step(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(k));
        return MotionJet::fromCoefficients(c);
      };
      for (std::size_t i = first; i < last; ++i) {
        out.position[i].x -= delta(2 * (i - first));
        out.position[i].y -= delta(2 * (i - first) + 1);
      }
    }
    return true;
  }

  bool run() {
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      const PointDefinition& d = m.points[i].definition;
      const PointDefinition& ds = s.points[i].definition;
      if (d.index() != ds.index()) return false;
      if (std::holds_alternative<FreePoint>(d)) {
        const std::size_t last = freeGroupEnd(m, i);
        if (!freeGroup(i, last)) return false;
        i = last - 1;
        continue;
      }
      std::optional<JetVector> placed;
      std::visit(
          [&](const auto& def) {
            using T = std::decay_t<decltype(def)>;
            if constexpr (!std::is_same_v<T, FreePoint>) placed = place(i, def, std::get<T>(ds));
          },
          d);
      if (!placed) return false;
      out.position[i] = *placed;
    }
    for (std::size_t k = 0; k < m.links.size(); ++k) {
      // The driven crank's angle is the input plus its phase, exactly, as the solver has it.
      const auto phase = crankPhaseOf(m, LinkId{k});
      const auto steppedPhase = crankPhaseOf(s, LinkId{k});
      if (phase && steppedPhase) {
        out.linkAngle[k] = input + number(*phase, *steppedPhase);
        continue;
      }
      const JetVector r = at(m.links[k].second) - at(m.links[k].first);
      out.linkAngle[k] = atan2(r.y, r.x);
    }
    return true;
  }
};

}  // namespace

bool differentiatePose(const Mechanism& mechanism, const Mechanism& stepped, const DriverState& driver,
                       std::span<const Eigen::Vector2d> nominal, PoseJet& out) {
  if (stepped.points.size() != mechanism.points.size() || stepped.links != mechanism.links ||
      stepped.constraints.size() != mechanism.constraints.size() || nominal.size() != mechanism.points.size())
    return false;
  out.position.assign(mechanism.points.size(), JetVector{});
  out.linkAngle.assign(mechanism.links.size(), MotionJet{});
  const MotionJet input = MotionJet::motion(driver.position, driver.velocity, driver.acceleration);
  return Differentiator{mechanism, stepped, nominal, input, out}.run();
}

}  // namespace linkwright::kinematics
