#include "tests/kinematics/soak/random_linkages.h"

#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace linkwright::test {
namespace k = kinematics;

namespace {

double uniform(std::mt19937& rng, double low, double high) { return low + (high - low) * unit(rng); }
double logUniform(std::mt19937& rng, double low, double high) {
  return std::exp(uniform(rng, std::log(low), std::log(high)));
}
bool chance(std::mt19937& rng, double p) { return unit(rng) < p; }
k::Branch branch(std::mt19937& rng) { return chance(rng, 0.5) ? k::Branch::Open : k::Branch::Crossed; }

// A linkage's scale: mostly ordinary, sometimes at either end of the input domain.
double scale(std::mt19937& rng, double spread) {
  const double r = unit(rng);
  if (r < 0.05) return k::kMinLength * 1.0000001;           // shortest links at the lower end
  if (r < 0.10) return k::kMaxLength / spread / 1.0000001;  // longest at the upper end
  return logUniform(rng, 1e-3, 1e3);
}

// Four lengths of the given spread; one in five made an exact change point (S + L = P + Q).
k::FourBarLengths fourBarLengths(std::mt19937& rng, double spread) {
  std::array<double, 4> l{};
  for (double& x : l) x = logUniform(rng, 1.0, spread);
  if (chance(rng, 0.2)) {
    std::array<double, 4> s = l;
    std::sort(s.begin(), s.end());
    // Replace the longest so that s0 + s3 = s1 + s2.
    const auto longest = std::max_element(l.begin(), l.end()) - l.begin();
    l[static_cast<std::size_t>(longest)] = s[1] + s[2] - s[0];
  }
  return {l[0], l[1], l[2], l[3]};
}

k::FourBarLengths scaled(const k::FourBarLengths& l, double f) {
  return {l.frame * f, l.crank * f, l.coupler * f, l.rocker * f};
}

template <typename T>
DrawnLinkage fromResult(k::Result<k::Mechanism> m, const T& describe) {
  DrawnLinkage d;
  std::ostringstream s;
  s.precision(17);
  describe(s);
  d.description = s.str();
  if (m) d.mechanism = std::move(*m);
  else d.refusal = m.error().message;
  return d;
}

DrawnLinkage fourBar(std::mt19937& rng) {
  const double spread = chance(rng, 0.1) ? 1e6 : 1e2;
  const double f = scale(rng, spread);
  const k::FourBarLengths l = scaled(fourBarLengths(rng, spread), f);
  const k::Branch b = branch(rng);
  std::optional<k::CouplerPointSpec> p;
  if (chance(rng, 0.5)) p = k::CouplerPointSpec{uniform(rng, -1, 1) * l.coupler, uniform(rng, -1, 1) * l.coupler};
  return fromResult(k::makeFourBar(l, b, "mm", p), [&](std::ostream& s) {
    s << "four-bar " << l.frame << "," << l.crank << "," << l.coupler << "," << l.rocker
      << (b == k::Branch::Open ? " open" : " crossed");
    if (p) s << " coupler point " << p->along << "," << p->across;
  });
}

DrawnLinkage sliderCrank(std::mt19937& rng) {
  const double f = scale(rng, 1e2);
  const double crank = f * logUniform(rng, 1.0, 10.0);
  const double rod = crank * logUniform(rng, 0.5, 10.0);
  const double offset = chance(rng, 0.3) ? 0.0 : uniform(rng, -1.2, 1.2) * rod;  // zero: collinear
  const k::SliderCrankGeometry g{crank, rod, offset, chance(rng, 0.3)};
  const k::Branch b = branch(rng);
  return fromResult(k::makeSliderCrank(g, b), [&](std::ostream& s) {
    s << "slider-crank crank " << g.crank << " rod " << g.rod << " offset " << g.offset
      << (g.reversed ? " reversed" : "");
  });
}

DrawnLinkage shaper(std::mt19937& rng) {
  const double f = scale(rng, 1e2);
  const double crank = f * logUniform(rng, 1.0, 10.0);
  // Crank-shaper (pivot outside the crank circle) or Whitworth (inside); on the axis sometimes.
  const double distance = crank * (chance(rng, 0.5) ? uniform(rng, 1.05, 8.0) : uniform(rng, 0.05, 0.95));
  const double direction = chance(rng, 0.2) ? -k::kPi / 2 : uniform(rng, -k::kPi, k::kPi);
  const Eigen::Vector2d pivot(distance * std::cos(direction), distance * std::sin(direction));
  const double rocker = (distance + crank) * uniform(rng, 1.05, 2.0);
  const double link = rocker * uniform(rng, 0.3, 1.5);
  const double guide = uniform(rng, 0.0, 1.2) * rocker + pivot.y();
  const k::ShaperGeometry g{crank, rocker, link, pivot, guide};
  return fromResult(k::makeShaper(g, branch(rng)), [&](std::ostream& s) {
    s << "shaper crank " << crank << " rocker " << rocker << " link " << link << " pivot " << pivot.x() << ","
      << pivot.y() << " guide " << guide;
  });
}

DrawnLinkage sixBar(std::mt19937& rng) {
  const double f = scale(rng, 1e2);
  k::SixBarGeometry g;
  g.kind = static_cast<k::SixBarKind>(rng() % 4);
  g.fourBar = scaled(fourBarLengths(rng, 10.0), f);
  g.fourBarBranch = branch(rng);
  const double size = std::max({g.fourBar.frame, g.fourBar.crank, g.fourBar.coupler, g.fourBar.rocker});
  g.first = {uniform(rng, 0.0, 1.0) * size, uniform(rng, -0.5, 0.5) * size};
  g.second = {uniform(rng, 0.0, 1.0) * size, uniform(rng, -0.5, 0.5) * size};
  g.groundPivot = Eigen::Vector2d(uniform(rng, -1.0, 2.0) * size, uniform(rng, -1.0, 1.0) * size);
  g.link5 = logUniform(rng, 0.3, 2.0) * size;
  g.link6 = logUniform(rng, 0.3, 2.0) * size;
  g.dyadBranch = branch(rng);
  return fromResult(k::makeSixBar(g), [&](std::ostream& s) {
    s << k::sixBarKindName(g.kind) << " four-bar " << g.fourBar.frame << "," << g.fourBar.crank << ","
      << g.fourBar.coupler << "," << g.fourBar.rocker << " P " << g.first.along << "," << g.first.across << " D "
      << g.second.along << "," << g.second.across << " O6 " << g.groundPivot.x() << "," << g.groundPivot.y()
      << " links " << g.link5 << "," << g.link6;
  });
}

// The Newton six-bars' own geometries with every length changed by up to ±3 %: random ones
// almost never assemble, and these still exercise Newton from guesses that are a little off.
DrawnLinkage newton(std::mt19937& rng) {
  const auto jitter = [&](double& x) { x *= uniform(rng, 0.97, 1.03); };
  if (chance(rng, 0.5)) {
    k::StephensonIIIGeometry g = k::kStephensonIIINewton;
    for (double* x : {&g.crank, &g.coupler, &g.cd, &g.ce, &g.de, &g.rocker4, &g.rocker6}) jitter(*x);
    return fromResult(k::makeStephensonIIINewton(g), [&](std::ostream& s) {
      s << "stephenson-iii newton crank " << g.crank << " coupler " << g.coupler << " cd " << g.cd << " ce " << g.ce
        << " de " << g.de << " rocker4 " << g.rocker4 << " rocker6 " << g.rocker6;
    });
  }
  k::StephensonIIGeometry g = k::kStephensonIINewton;
  for (double* x : {&g.crank, &g.j1j2, &g.j1j3, &g.j2j3, &g.j5j4, &g.j5j6, &g.j4j6, &g.link5, &g.link6}) jitter(*x);
  return fromResult(k::makeStephensonIINewton(g), [&](std::ostream& s) {
    s << "stephenson-ii newton crank " << g.crank << " j1j2 " << g.j1j2 << " j1j3 " << g.j1j3 << " j2j3 " << g.j2j3
      << " j5j4 " << g.j5j4 << " j5j6 " << g.j5j6 << " j4j6 " << g.j4j6 << " links " << g.link5 << "," << g.link6;
  });
}

// A linkage driven other than by a crank, swept over its driver's whole travel (which may run
// out of reach: the sweep reports those samples, the soak checks the rest).
DrawnLinkage driven(std::mt19937& rng) {
  const double f = scale(rng, 1e2);
  DrawnLinkage d;
  // Eigen::Vector2d, not auto: an Eigen product expression would outlive its temporary vector.
  const auto point = [&](double spread) -> Eigen::Vector2d {
    const double x = uniform(rng, -spread, spread);
    const double y = uniform(rng, -spread, spread);
    return Eigen::Vector2d(x, y) * f;
  };
  const double which = unit(rng);
  if (which < 0.5) {
    const double upper = f * logUniform(rng, 1.0, 10.0);
    const double forearm = f * logUniform(rng, 1.0, 10.0);
    const double reach = (upper + forearm) / f;
    k::PathShape path;
    const double shape = unit(rng);
    if (shape < 0.4) path = k::PolylinePath{{point(reach), point(reach)}};
    else if (shape < 0.7) path = k::PolylinePath{{point(reach), point(reach), point(reach)}};
    else
      path = k::ArcPath{point(0.5 * reach), f * logUniform(rng, 0.3, reach), uniform(rng, -k::kPi, k::kPi),
                        (chance(rng, 0.5) ? -1.0 : 1.0) * uniform(rng, 0.2, 2.0 * k::kPi)};
    const k::Branch elbow = branch(rng);
    d = fromResult(k::makeTwoLinkArm({upper, forearm, path, elbow, "mm"}), [&](std::ostream& s) {
      s << "arm " << upper << "," << forearm << (elbow == k::Branch::Open ? " open" : " crossed");
      if (const auto* line = std::get_if<k::PolylinePath>(&path)) {
        s << " polyline";
        for (const Eigen::Vector2d& v : line->vertices) s << " " << v.x() << "," << v.y();
      } else {
        const auto& arc = std::get<k::ArcPath>(path);
        s << " arc centre " << arc.centre.x() << "," << arc.centre.y() << " radius " << arc.radius << " start "
          << arc.startAngle << " sweep " << arc.sweep;
      }
    });
    if (d.mechanism) d.inputTo = k::pathLength(path);
    // An arc tighter than the arm bends the tip's path on its own scale.
    const auto* arc = std::get_if<k::ArcPath>(&path);
    d.inputScale = arc != nullptr ? std::min(upper + forearm, arc->radius) : upper + forearm;
  } else if (which < 0.75) {
    const double crank = f * logUniform(rng, 1.0, 10.0);
    const double rod = crank * logUniform(rng, 1.05, 10.0);
    const k::Branch b = branch(rng);
    d = fromResult(k::makePistonDriven({crank, rod, b, "mm"}),
                   [&](std::ostream& s) { s << "piston-driven crank " << crank << " rod " << rod; });
    // Between the dead centres, where the crank cannot be driven from the piston.
    d.inputFrom = 0.01 * crank;
    d.inputTo = 1.99 * crank;
    d.inputScale = crank;
  } else {
    const Eigen::Vector2d base = point(5.0);
    const double eye = f * logUniform(rng, 0.3, 5.0);
    const double tip = eye * uniform(rng, 0.5, 3.0);
    const k::Branch b = branch(rng);
    d = fromResult(k::makeCylinderRocker({base, eye, tip, b, "mm"}), [&](std::ostream& s) {
      s << "cylinder rocker base " << base.x() << "," << base.y() << " eye " << eye << " tip " << tip;
    });
    // Between the cylinder's folded and stretched limits, where the boom toggles.
    const double far = base.norm();
    d.inputFrom = std::abs(far - eye) + 0.01 * std::min(far, eye);
    d.inputTo = far + eye - 0.01 * std::min(far, eye);
    d.inputScale = eye;
  }
  return d;
}

}  // namespace

double unit(std::mt19937& rng) { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; }

std::string kindName(LinkageKind kind) {
  switch (kind) {
  case LinkageKind::FourBar: return "four-bar";
  case LinkageKind::SliderCrank: return "slider-crank";
  case LinkageKind::Shaper: return "shaper";
  case LinkageKind::SixBar: return "six-bar";
  case LinkageKind::Newton: return "newton";
  case LinkageKind::Driven: return "driven";
  }
  return "?";
}

DrawnLinkage drawLinkage(LinkageKind kind, std::mt19937& rng) {
  switch (kind) {
  case LinkageKind::FourBar: return fourBar(rng);
  case LinkageKind::SliderCrank: return sliderCrank(rng);
  case LinkageKind::Shaper: return shaper(rng);
  case LinkageKind::SixBar: return sixBar(rng);
  case LinkageKind::Newton: return newton(rng);
  case LinkageKind::Driven: return driven(rng);
  }
  return {};
}

}  // namespace linkwright::test
