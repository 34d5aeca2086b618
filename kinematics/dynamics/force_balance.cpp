#include "kinematics/dynamics/force_balance.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/rigid_bodies.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace linkwright::kinematics {
namespace {

using Complex = std::complex<double>;

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

// A body's frame: its pivot (or first joint) and the unit vector toward its other joint.
struct Frame {
  Eigen::Vector2d origin;
  Eigen::Vector2d axis;
  double length = 0.0;
};

Frame frameOf(const Pose& pose, PointId from, PointId to) {
  const Eigen::Vector2d d = pose.position[to.index] - pose.position[from.index];
  return {pose.position[from.index], d / d.norm(), d.norm()};
}

Complex inFrame(const Frame& f, const Eigen::Vector2d& world) {
  const Eigen::Vector2d v = world - f.origin;
  return {v.dot(f.axis), cross(f.axis, v)};
}

Eigen::Vector2d toWorld(const Frame& f, Complex z) { return f.origin + z.real() * f.axis + z.imag() * perp(f.axis); }

// A link-frame point with round-off (below 1e-12 of the link's length) written as 0.
LinkFramePoint cleaned(double along, double across, double length) {
  const auto clean = [&](double v) { return std::abs(v) <= 1e-12 * length ? 0.0 : v; };
  return {clean(along), clean(across)};
}

// A body's mass (kg) and first moment about its frame's origin (kg·length unit, in its frame).
struct MassSum {
  double mass = 0.0;
  Complex moment;
};

// Where each link mass's centre is at `pose`, and on which body.
struct PlacedMass {
  BodyId body;
  double mass = 0.0;
  Eigen::Vector2d centre;
};

std::vector<PlacedMass> placedMasses(const Mechanism& m, const LinkageDynamics& d, const BodyModel& bodies,
                                     const Pose& pose) {
  std::vector<PlacedMass> placed;
  for (const LinkMass& lm : d.links) {
    const LinkId id = *m.findLink(lm.link);
    const Link& link = m.links[id.index];
    const Eigen::Vector2d a = pose.position[link.first.index];
    const Eigen::Vector2d ab = pose.position[link.second.index] - a;
    const Eigen::Vector2d e = ab / ab.norm();
    const LinkFramePoint c = lm.centre.value_or(LinkFramePoint{0.5 * ab.norm(), 0.0});
    placed.push_back({bodies.linkBody[id.index], lm.mass, a + c.along * e + c.across * perp(e)});
  }
  for (const SliderMass& s : d.sliders) {
    const PointId pin = *m.findPoint(s.point);
    placed.push_back(
        {bodies.findSlider(SliderKey{pin, s.guide}).value_or(kGroundBody), s.mass, pose.position[pin.index]});
  }
  return placed;
}

MassSum sumOn(const std::vector<PlacedMass>& placed, BodyId body, const Frame& f) {
  MassSum s;
  for (const PlacedMass& p : placed)
    if (p.body == body) {
      s.mass += p.mass;
      s.moment += p.mass * inFrame(f, p.centre);
    }
  return s;
}

std::optional<BodyId> bodyHolding(const BodyModel& bodies, PointId a, PointId b) {
  for (std::size_t k = 1; k < bodies.bodies.size(); ++k)
    if (bodies.bodies[k].kind == BodyKind::Rigid && bodies.holds(BodyId{k}, a) && bodies.holds(BodyId{k}, b))
      return BodyId{k};
  return std::nullopt;
}

// A pose to measure the bodies in: the first input from 0° in steps of 10° that assembles.
std::optional<Pose> somePose(const Mechanism& m) {
  for (int k = 0; k < 36; ++k) {
    auto pose = solvePose(m, DriverState{k * std::numbers::pi / 18.0, 0.0, 0.0}, SolveRequest{false, false});
    if (pose) return std::move(*pose);
  }
  return std::nullopt;
}

// The point mass on `body`'s first link that adds `change` to its first moment, `radius`
// link-lengths from the frame's origin; none when the change is round-off.
Result<std::optional<Counterweight>> counterweight(const Mechanism& m, const BodyModel& bodies, const Pose& pose,
                                                   BodyId body, const Frame& f, Complex change, double radius,
                                                   const std::string& role, double scale) {
  if (std::abs(change) <= 1e-14 * scale) return std::optional<Counterweight>{};
  const Body& b = bodies.bodies[body.index];
  if (b.links.empty())
    return invalid("linkage", "the " + role + " has no link to carry a counterweight: give it one in the design");
  const double r = radius * f.length;
  const Eigen::Vector2d world = toWorld(f, r * change / std::abs(change));
  const Link& link = m.links[b.links.front().index];
  const Frame lf = frameOf(pose, link.first, link.second);
  const Complex at = inFrame(lf, world);
  return std::optional<Counterweight>{
      Counterweight{link.name, std::abs(change) / r, cleaned(at.real(), at.imag(), lf.length)}};
}

// `link`'s mass properties with the point mass `c` added: the masses summed, the centre their
// centre of mass, the inertia about it by the parallel-axis theorem (`metres` per length unit).
LinkMass withCounterweight(const Mechanism& m, const std::optional<LinkMass>& link, const Counterweight& c,
                           double metres) {
  if (!link) return {c.link, c.mass, c.centre, 0.0};
  const double length = linkLength(m, *m.findLink(c.link));
  const LinkFramePoint own = link->centre.value_or(LinkFramePoint{0.5 * length, 0.0});
  const double ownInertia = link->inertia.value_or(link->mass * length * metres * length * metres / 12.0);
  const double total = link->mass + c.mass;
  const Eigen::Vector2d a(own.along, own.across), b(c.centre.along, c.centre.across);
  const Eigen::Vector2d centre = (link->mass * a + c.mass * b) / total;
  const double inertia =
      ownInertia + metres * metres * (link->mass * (a - centre).squaredNorm() + c.mass * (b - centre).squaredNorm());
  return {c.link, total, cleaned(centre.x(), centre.y(), length), inertia};
}

}  // namespace

Result<ForceBalance> balanceShakingForce(const Mechanism& m, const LinkageDynamics& d, const BalanceOptions& o) {
  if (!(o.reciprocatingFraction >= 0.0 && o.reciprocatingFraction <= 1.0))
    return invalid("fraction", "the fraction of the reciprocating mass to balance must be between 0 and 1 (got " +
                                   formatNumber(o.reciprocatingFraction) + ")");
  if (!(o.radius >= 0.1 && o.radius <= 10.0))
    return invalid("radius", "the counterweight's radius must be between 0.1 and 10 times its link's length (got " +
                                 formatNumber(o.radius) + ")");
  if (auto e = checkDynamics(m, d)) return *e;
  if (d.links.empty() && d.sliders.empty())
    return invalid("dynamics", "there are no masses to balance: give the links their masses first");
  const auto fourBar = asFourBar(m, PointsOnLinks::AnyLink);
  const auto sliderCrank = fourBar ? std::nullopt : asSliderCrank(m, PointsOnLinks::AnyLink);
  if (!fourBar && !sliderCrank)
    return invalid("linkage", "shaking-force balance by counterweights is for a four-bar or a slider-crank");
  const auto bodies = bodiesOf(m);
  if (!bodies) return bodies.error();
  const auto pose = somePose(m);
  if (!pose)
    return Error{ErrorCode::NotAssemblable, "linkage", "the linkage cannot be assembled to measure its bodies"};
  const std::vector<PlacedMass> placed = placedMasses(m, d, *bodies, *pose);
  double totalMass = 0.0;
  for (const PlacedMass& p : placed) totalMass += p.mass;

  const auto metres = metresPerLengthUnit(m.lengthUnit);
  if (!metres)
    return invalid("lengthUnit",
                   "the length unit \"" + m.lengthUnit + "\" has no size in metres to weigh counterweights in");

  ForceBalance result;
  result.balanced = d;
  // A link holds one set of mass properties (mass_properties.h): a counterweight bolted to it
  // joins them.
  const auto add = [&](const Result<std::optional<Counterweight>>& c) -> std::optional<Error> {
    if (!c) return c.error();
    if (!*c) return std::nullopt;
    result.counterweights.push_back(**c);
    auto& links = result.balanced.links;
    const auto own = std::find_if(links.begin(), links.end(), [&](const LinkMass& l) { return l.link == (*c)->link; });
    if (own == links.end()) links.push_back(withCounterweight(m, std::nullopt, **c, *metres));
    else *own = withCounterweight(m, *own, **c, *metres);
    return std::nullopt;
  };
  if (fourBar) {
    const auto crank = bodyHolding(*bodies, fourBar->o2, fourBar->b);
    const auto coupler = bodyHolding(*bodies, fourBar->b, fourBar->c);
    const auto rocker = bodyHolding(*bodies, fourBar->o4, fourBar->c);
    if (!crank || !coupler || !rocker)
      return invalid("linkage", "the four-bar's crank, coupler and rocker were not found");
    const Frame f2 = frameOf(*pose, fourBar->o2, fourBar->b);
    const Frame f3 = frameOf(*pose, fourBar->b, fourBar->c);
    const Frame f4 = frameOf(*pose, fourBar->o4, fourBar->c);
    const MassSum s2 = sumOn(placed, *crank, f2), s3 = sumOn(placed, *coupler, f3), s4 = sumOn(placed, *rocker, f4);
    const double scale = totalMass * (f2.length + f3.length + f4.length);
    const Complex need2 = s3.moment * (f2.length / f3.length) - s3.mass * f2.length;
    const Complex need4 = -s3.moment * (f4.length / f3.length);
    if (auto e = add(counterweight(m, *bodies, *pose, *crank, f2, need2 - s2.moment, o.radius, "crank", scale)))
      return *e;
    if (auto e = add(counterweight(m, *bodies, *pose, *rocker, f4, need4 - s4.moment, o.radius, "rocker", scale)))
      return *e;
    result.method =
        "four-bar: complete shaking-force balance (Berkof and Lowen), counterweights on the crank and "
        "the rocker";
    return result;
  }
  const auto crank = bodyHolding(*bodies, sliderCrank->o2, sliderCrank->b);
  const auto rod = bodyHolding(*bodies, sliderCrank->b, sliderCrank->c);
  if (!crank || !rod) return invalid("linkage", "the slider-crank's crank and rod were not found");
  const Frame f2 = frameOf(*pose, sliderCrank->o2, sliderCrank->b);
  const Frame f3 = frameOf(*pose, sliderCrank->b, sliderCrank->c);
  const MassSum s2 = sumOn(placed, *crank, f2), s3 = sumOn(placed, *rod, f3);
  double slider = 0.0;
  for (const PlacedMass& p : placed)
    if (bodies->bodies[p.body.index].kind == BodyKind::Slider) slider += p.mass;
  const double atC = s3.moment.real() / f3.length;  // the rod's share at its wrist pin
  const double reciprocating = slider + atC;
  const Complex rotating = s2.moment + (s3.mass - atC) * f2.length;
  const Complex change = -rotating - o.reciprocatingFraction * reciprocating * f2.length;
  const double scale = totalMass * (f2.length + f3.length);
  if (auto e = add(counterweight(m, *bodies, *pose, *crank, f2, change, o.radius, "crank", scale))) return *e;
  result.method = "slider-crank: crank counterweight for the rotating masses and " +
                  formatShort(100.0 * o.reciprocatingFraction) + " % of the reciprocating ones";
  return result;
}

}  // namespace linkwright::kinematics
