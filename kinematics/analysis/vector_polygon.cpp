#include "kinematics/analysis/vector_polygon.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep_columns.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace linkwright::kinematics {
namespace {

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return text;
}

std::string joined(const std::vector<std::string>& terms) {
  std::string text;
  for (const std::string& t : terms) text += (text.empty() ? "" : " + ") + t;
  return text;
}

// A body the relative motion happens on: a reference point of it, its rates, its name.
struct Body {
  PointId reference;
  double omega = 0.0;
  double alpha = 0.0;
  std::optional<LinkId> link;
  std::string name;  // "the coupler", "the slotted link O4–D"
};

// One side of a point's equation: the terms after the known image it starts from, and where
// the chain of arrows ends.
struct Side {
  std::vector<std::string> terms;
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  std::string rule;  // what a lone term is, when it is the point's own: "ω × O2B"
};

class Builder {
public:
  Builder(const Mechanism& mechanism, const Pose& solved, PolygonKind kind)
      : m(mechanism), pose(solved), vel(kind == PolygonKind::Velocity) {
    out.kind = kind;
    out.unit = columnUnit(vel ? ColumnQuantity::PointVx : ColumnQuantity::PointAx, mechanism.lengthUnit);
    out.images.push_back({"o", PointId{0}, Eigen::Vector2d::Zero(), false});
  }

  VectorPolygon run() {
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      const PointId id{i};
      if (isGround(id)) continue;
      std::visit([&](const auto& d) { point(id, d); }, m.points[i].definition);
      out.images.push_back({lowerCase(name(id)), id, image(id), false});
    }
    boundingBox();
    return std::move(out);
  }

private:
  const Mechanism& m;
  const Pose& pose;
  const bool vel;
  VectorPolygon out;

  const std::string& name(PointId p) const { return m.points[p.index].name; }
  bool isGround(PointId p) const { return std::holds_alternative<GroundPoint>(m.points[p.index].definition); }
  Eigen::Vector2d image(PointId p) const { return vel ? pose.velocity[p.index] : pose.acceleration[p.index]; }
  Eigen::Vector2d position(PointId p) const { return pose.position[p.index]; }
  std::string letter() const { return vel ? "V_" : "A_"; }

  std::optional<LinkId> linkJoining(PointId a, PointId b) const {
    for (std::size_t k = 0; k < m.links.size(); ++k) {
      const Link& l = m.links[k];
      if ((l.first == a && l.second == b) || (l.first == b && l.second == a)) return LinkId{k};
    }
    return std::nullopt;
  }

  // The rigid body through p and q: the mechanism's link joining them if there is one (its
  // solver rates), else the bar p–q with rates from its two points, as the solver gets them.
  Body bodyThrough(PointId p, PointId q) const {
    if (const auto k = linkJoining(p, q))
      return {p, pose.linkOmega[k->index], pose.linkAlpha[k->index], k, "the " + m.links[k->index].name};
    const Eigen::Vector2d r = position(q) - position(p);
    const double inv = 1.0 / r.squaredNorm();
    return {p, cross(r, pose.velocity[q.index] - pose.velocity[p.index]) * inv,
            cross(r, pose.acceleration[q.index] - pose.acceleration[p.index]) * inv, std::nullopt,
            "the bar " + name(p) + "–" + name(q)};
  }

  Eigen::Vector2d add(const std::string& label, VectorTerm term, const Eigen::Vector2d& from, const Eigen::Vector2d& v,
                      PointId owner, const std::optional<LinkId>& link, const std::string& meaning) {
    const int step = static_cast<int>(out.vectors.size()) + 1;
    out.vectors.push_back({label, term, from, from + v, owner, link, meaning, step});
    return from + v;
  }

  // Q (named qName, at qPos) relative to the body's reference point: ω × r, or −ω² r and α × r.
  Side rigid(const Body& body, const std::string& qName, const Eigen::Vector2d& qPos, PointId owner) {
    const PointId ref = body.reference;
    const Eigen::Vector2d r = qPos - position(ref);
    const bool grounded = isGround(ref);
    const std::string suffix = qName + (grounded ? "" : name(ref));
    const std::string rel = grounded ? qName + " turning about " + name(ref) : qName + " relative to " + name(ref);
    const std::string line = name(ref) + qName;
    Side side;
    if (!grounded) side.terms.push_back(letter() + name(ref));
    Eigen::Vector2d at = image(ref);
    if (vel) {
      at = add("V_" + suffix, VectorTerm::Relative, at, body.omega * perp(r), owner, body.link,
               rel + " on " + body.name + ": ω × " + line + ", ⟂ " + line);
      side.terms.push_back("V_" + suffix);
      side.rule = "ω × " + line;
    } else {
      at = add("A^n_" + suffix, VectorTerm::Normal, at, -body.omega * body.omega * r, owner, body.link,
               "normal acceleration of " + rel + " on " + body.name + ": ω²·" + line + ", from " + qName + " towards " +
                   name(ref));
      at = add("A^t_" + suffix, VectorTerm::Tangential, at, body.alpha * perp(r), owner, body.link,
               "tangential acceleration of " + rel + " on " + body.name + ": α × " + line + ", ⟂ " + line);
      side.terms.push_back("A^n_" + suffix);
      side.terms.push_back("A^t_" + suffix);
    }
    side.end = at;
    return side;
  }

  // Point c sliding along direction u of `body` (nullopt: the ground): C' the body's point
  // under C, then Coriolis (accelerations on a turning body), then the slide along u.
  Side slide(PointId c, const Eigen::Vector2d& u, const std::optional<Body>& body, PointId owner,
             const std::string& guide) {
    const std::string cName = name(c);
    if (!body) {
      const Eigen::Vector2d v = image(c).dot(u) * u;
      add(letter() + cName, VectorTerm::Sliding, Eigen::Vector2d::Zero(), v, owner, std::nullopt,
          cName + " sliding along " + guide + " fixed to the ground, ∥ the guide");
      return {{letter() + cName}, v, {}};
    }
    const std::string prime = cName + "'";
    Side side = rigid(*body, prime, position(c), owner);
    out.images.push_back({lowerCase(prime), c, side.end, true});
    const Eigen::Vector2d r = position(c) - position(body->reference);
    const Eigen::Vector2d vPrime = pose.velocity[body->reference.index] + body->omega * perp(r);
    const Eigen::Vector2d vSlide = (pose.velocity[c.index] - vPrime).dot(u) * u;
    const std::string rel = cName + " relative to " + prime + " (" + prime + " the point of " + body->name + " under " +
                            cName + ") sliding along " + guide;
    if (vel) {
      side.end = add("V_" + cName + prime, VectorTerm::Sliding, side.end, vSlide, owner, body->link, rel + ", ∥ it");
      side.terms.push_back("V_" + cName + prime);
      return side;
    }
    const Eigen::Vector2d coriolis = 2.0 * body->omega * perp(vSlide);
    side.end = add("A^c_" + cName, VectorTerm::Coriolis, side.end, coriolis, owner, body->link,
                   "Coriolis acceleration of " + cName + " sliding on " + body->name + ": 2ω × V_" + cName + prime +
                       ", ⟂ " + guide);
    const Eigen::Vector2d aSlide = (pose.acceleration[c.index] - side.end).dot(u) * u;
    side.end = add("A_" + cName + prime, VectorTerm::Sliding, side.end, aSlide, owner, body->link, rel + ", ∥ it");
    side.terms.push_back("A^c_" + cName);
    side.terms.push_back("A_" + cName + prime);
    return side;
  }

  Side guideSide(const Guide& g, PointId c, PointId owner) {
    const GuideLine line = guideLineAt(m, g, pose);
    if (!g.link) return slide(c, line.direction, std::nullopt, owner, "the guide");
    const std::size_t k = g.link->index;
    const Body body{m.links[k].first, pose.linkOmega[k], pose.linkAlpha[k], g.link, "the " + m.links[k].name};
    return slide(c, line.direction, body, owner, "the guide on the " + m.links[k].name);
  }

  // Sides that only restate the point (V_C of a rocker about a ground pivot) are left out;
  // if that leaves none, the point's one term is spelled out (V_B = ω × O2B).
  void equation(PointId owner, PointId subject, const std::vector<Side>& sides) {
    const std::string lhs = letter() + name(subject);
    std::string text = lhs;
    for (const Side& s : sides)
      if (const std::string t = joined(s.terms); t != lhs) text += " = " + t;
    if (text == lhs && !sides.empty() && !sides.front().rule.empty()) text += " = " + sides.front().rule;
    std::vector<Eigen::Vector2d> ends;
    for (const Side& s : sides) ends.push_back(s.end);
    out.equations.push_back({owner, subject, text, std::move(ends), image(subject)});
  }

  void point(PointId, const GroundPoint&) {}
  void point(PointId id, const CrankPoint& c) {
    equation(id, id, {rigid(bodyThrough(c.pivot, id), name(id), position(id), id)});
  }
  void point(PointId id, const RrrPoint& r) {
    const Side s1 = rigid(bodyThrough(r.first, id), name(id), position(id), id);
    const Side s2 = rigid(bodyThrough(r.second, id), name(id), position(id), id);
    equation(id, id, {s1, s2});
  }
  void point(PointId id, const RrpPoint& r) {
    const Side s1 = rigid(bodyThrough(r.first, id), name(id), position(id), id);
    const Side s2 = guideSide(r.guide, id, id);
    equation(id, id, {s1, s2});
  }
  void point(PointId id, const PrpPoint& p) {
    const Side s1 = guideSide(p.first, id, id);
    const Side s2 = guideSide(p.second, id, id);
    equation(id, id, {s1, s2});
  }
  // The block at `through` slides in the slot of the link pivot–id: first the block's
  // equation (its image is known), then the slotted link's image of the tip.
  void point(PointId id, const RprPoint& r) {
    const Body slot = bodyThrough(r.pivot, id);
    const Eigen::Vector2d u = (position(r.through) - position(r.pivot)).normalized();
    const Side block = slide(r.through, u, slot, id, "the slot of " + slot.name);
    equation(id, r.through, {block});
    const Side tip = rigid(slot, name(id), position(id), id);
    equation(id, id, {tip});
  }
  void point(PointId id, const AttachedPoint& a) {
    const Link& l = m.links[a.link.index];
    const Body body{l.first, pose.linkOmega[a.link.index], pose.linkAlpha[a.link.index], a.link, "the " + l.name};
    equation(id, id, {rigid(body, name(id), position(id), id)});
  }
  // A linear actuator: the rigid link from `first`, and the cylinder turning about its base
  // while it extends (its rates from the line base–C: φ̇ = r×ṙ/|r|², φ̈ = r×r̈/|r|² − 2φ̇ r·ṙ/|r|²).
  void point(PointId id, const ActuatorPoint& a) {
    const Side s1 = rigid(bodyThrough(a.first, id), name(id), position(id), id);
    const Eigen::Vector2d r = position(id) - position(a.base);
    const Eigen::Vector2d rDot = pose.velocity[id.index] - pose.velocity[a.base.index];
    const Eigen::Vector2d rDdot = pose.acceleration[id.index] - pose.acceleration[a.base.index];
    const double inv = 1.0 / r.squaredNorm();
    const double w = cross(r, rDot) * inv;
    const double al = cross(r, rDdot) * inv - 2.0 * w * r.dot(rDot) * inv;
    const Body cylinder{a.base, w, al, std::nullopt, "the actuator " + name(a.base) + "–" + name(id)};
    const Side s2 = slide(id, r.normalized(), cylinder, id, "the actuator's axis");
    equation(id, id, {s1, s2});
  }
  void absolute(PointId id, const std::string& why) {
    add(letter() + name(id), VectorTerm::Absolute, Eigen::Vector2d::Zero(), image(id), id, std::nullopt,
        name(id) + " from the pole: " + why);
  }
  void point(PointId id, const PathPoint&) { absolute(id, "the driven point on its path"); }
  void point(PointId id, const FreePoint&) { absolute(id, "a free point (Newton), no dyad equation"); }

  void boundingBox() {
    Eigen::Vector2d lo = Eigen::Vector2d::Zero();
    Eigen::Vector2d hi = Eigen::Vector2d::Zero();
    const auto grow = [&](const Eigen::Vector2d& p) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    };
    for (const PolygonImage& im : out.images) grow(im.position);
    for (const PolygonVector& v : out.vectors) {
      grow(v.from);
      grow(v.to);
    }
    out.lower = lo;
    out.upper = hi;
  }
};

}  // namespace

VectorPolygon velocityPolygon(const Mechanism& mechanism, const Pose& pose) {
  return Builder(mechanism, pose, PolygonKind::Velocity).run();
}

VectorPolygon accelerationPolygon(const Mechanism& mechanism, const Pose& pose) {
  return Builder(mechanism, pose, PolygonKind::Acceleration).run();
}

Result<ClassroomPolygons> polygonsAt(const Mechanism& mechanism, const DriverState& driver) {
  auto pose = solvePose(mechanism, driver);
  if (!pose) return pose.error();
  ClassroomPolygons result{std::move(pose).value(), {}, {}};
  result.velocity = velocityPolygon(mechanism, result.pose);
  result.acceleration = accelerationPolygon(mechanism, result.pose);
  return result;
}

}  // namespace linkwright::kinematics

namespace linkwright::kinematics {

std::optional<Error> checkPolygonInput(const Mechanism& mechanism, const std::string& source) {
  if (inputKind(mechanism) == InputKind::Angle) return std::nullopt;
  return Error{ErrorCode::InvalidStructure, "mechanism",
               "polygon needs a crank-driven linkage (" + source + " is driven by its " + inputName(mechanism) + ")"};
}

}  // namespace linkwright::kinematics
