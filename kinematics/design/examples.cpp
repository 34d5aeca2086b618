#include "kinematics/design/examples.h"

#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/units.h"

namespace linkwright::kinematics {

LinkageDynamics funshoFourBarDynamics() {
  LinkageDynamics d;
  d.links = {{"crank", 0.2, LinkFramePoint{5.0, 0.0}, 1e-5},
             {"coupler", 0.6, LinkFramePoint{17.5, 0.0}, 4e-4},
             {"rocker", 0.4, LinkFramePoint{10.0, 0.0}, 8e-5}};
  return d;
}

namespace {

// A seed's four-bar, in millimetres on its open branch, over a full turn.
Example fourBarExample(std::string name, std::string description, const FourBarLengths& lengths, double omega,
                       double stepDeg, std::optional<CouplerPointSpec> couplerPoint = std::nullopt,
                       LinkageDynamics dynamics = {}) {
  return {std::move(name),
          std::move(description),
          "four-bar",
          makeFourBar(lengths, Branch::Open, "mm", couplerPoint).value(),
          omega,
          0.0,
          0.0,
          360.0,
          stepDeg,
          std::move(dynamics)};
}

// Any other linkage over a full turn every degree.
Example linkageExample(std::string name, std::string description, std::string kind, Mechanism mechanism, double omega) {
  return {
      std::move(name), std::move(description), std::move(kind), std::move(mechanism), omega, 0.0, 0.0, 360.0, 1.0, {}};
}

// The six-bars are the thesis crank-rocker (60/25/70/45 mm) grown by one dyad, at 60 rpm;
// their dimensions keep every transmission angle above 20° over the whole turn.
Example sixBarExample(const SixBarGeometry& g, std::string description) {
  return linkageExample(sixBarKindName(g.kind), std::move(description), sixBarKindName(g.kind), makeSixBar(g).value(),
                        2.0 * kPi);
}

// A linkage whose driver follows `law` from time 0 to `duration`, at `samples` instants. Its
// input grid (for a user who switches the time base off) covers the same travel at the
// law's mean speed.
Example timedExample(std::string name, std::string description, std::string kind, Mechanism mechanism, MotionLaw law,
                     double duration, std::size_t samples) {
  const double from = motionAt(law, 0.0).position;
  const double to = motionAt(law, duration).position;
  Example e = linkageExample(std::move(name), std::move(description), std::move(kind), std::move(mechanism),
                             (to - from) / duration);
  const bool crank = inputKind(e.mechanism) == InputKind::Angle;
  e.fromDeg = crank ? radToDeg(from) : from;
  e.toDeg = crank ? radToDeg(to) : to;
  e.stepDeg = (e.toDeg - e.fromDeg) / static_cast<double>(samples - 1);
  e.time = TimeBase{std::move(law), 0.0, duration};
  e.timeSamples = samples;
  return e;
}

// Seed 004's arm: r1 = 0.3 m, r2 = 0.2 m, the tip from (0.3, 0) to (0, 0.3) m at 2 m/s, the
// elbow down (its plots have θ1 rising from −39° to 51°); its MATLAB steps x by 0.003 m: 101
// samples.
Example seedArmExample() {
  const PolylinePath line{{{0.3, 0.0}, {0.0, 0.3}}};
  const double speed = 2.0;
  return timedExample("seed-arm",
                      "two-link arm 0.3 m and 0.2 m, its tip driven from (0.3, 0) to (0, 0.3) m at 2 m/s, elbow "
                      "down (seed 004's welding arm, by inverse kinematics)",
                      "two-link arm", makeTwoLinkArm({0.3, 0.2, line, Branch::Crossed, "m"}).value(),
                      ConstantVelocity{0.0, speed}, pathLength(line) / speed, 101);
}

}  // namespace

std::vector<Example> examples() {
  return {
      fourBarExample(
          "thesis-crank-rocker",
          "crank-rocker 60/25/70/45 mm at 10 rpm (Sharifgalieva thesis, Excel and SolidWorks tables every 30°)",
          kThesisCrankRocker, rpmToRadPerSec(10.0), 30.0),
      fourBarExample("alvi-fourbar",
                     "four-bar AD 80, AB 20, BC 66, CD 56 mm at 10.5 rad/s (Alvi et al., both branches every 40°)",
                     {80.0, 20.0, 66.0, 56.0}, 10.5, 40.0),
      fourBarExample("miranda-fourbar",
                     "four-bar frame 250, crank 100, coupler 225, rocker 150 mm at 11 Hz, P at the coupler's middle "
                     "(Miranda et al., SolidWorks coupler extremes at 11 and 15 Hz)",
                     {250.0, 100.0, 225.0, 150.0}, 2.0 * kPi * 11.0, 1.0, CouplerPointSpec{112.5, 0.0}),
      fourBarExample("funsho-fourbar",
                     "four-bar AB 10, BC 35, CD 20, AD 30 mm, crank at 100 rad/s, with masses and inertias: joint "
                     "forces and motor torque (Funsho, seed 004's MATLAB inverse dynamics)",
                     {30.0, 10.0, 35.0, 20.0}, 100.0, 5.0, std::nullopt, funshoFourBarDynamics()),
      linkageExample("ls3-engine",
                     "Chevrolet LS3 piston: stroke 92 mm (crank 46 mm), connecting rod 6.098 in, crank at 110 Hz = "
                     "6600 rpm (Miranda et al., SolidWorks piston extremes)",
                     "slider-crank", makeSliderCrank(kLs3Engine).value(), 2.0 * kPi * 110.0),
      linkageExample("shaper",
                     "crank-shaper quick return: crank 100, slotted rocker 400, link 150 mm, rocker pivot 200 mm below "
                     "and 40 mm beside the crank, ram guide 220 mm above it, crank at 3 Hz (Miranda et al.)",
                     "shaper", makeShaper(kSeedShaper).value(), 2.0 * kPi * 3.0),
      linkageExample("whitworth",
                     "Whitworth quick return: the seed shaper's crank (100 mm) with the slotted link's pivot 40 mm "
                     "below the crank centre, inside the crank circle, so it turns fully; slotted link 120, link 150 "
                     "mm, ram guide through the pivot",
                     "whitworth", makeShaper(kWhitworth).value(), 2.0 * kPi * 3.0),
      sixBarExample(kWattISixBar,
                    "Watt I six-bar: the thesis crank-rocker with links 5 and 6 from its coupler to its rocker"),
      sixBarExample(
          kWattIISixBar,
          "Watt II six-bar: two four-bars in series, the thesis crank-rocker driving a second rocker about O6"),
      sixBarExample(kStephensonISixBar, "Stephenson I six-bar: links 5 and 6 from a point on the crank to the rocker"),
      sixBarExample(kStephensonIIISixBar,
                    "Stephenson III six-bar: links 5 and 6 from the coupler to a third ground pivot O6"),
      seedArmExample(),
      timedExample("piston-driven",
                   "slider-crank driven from its piston (a compressor's linkage worked from the piston side): crank "
                   "40, rod 140 mm; the piston moves 78 of its 80 mm stroke in 50 ms on a 3-4-5 polynomial, "
                   "stopping 1 mm short of each dead centre, where the crank cannot be driven from the piston",
                   "slider-crank", makePistonDriven({40.0, 140.0, Branch::Open, "mm"}).value(),
                   PolynomialRise{1.0, 78.0, 0.05}, 0.05, 201),
      timedExample("excavator-boom",
                   "excavator-style boom: a rocker about O driven by a hydraulic cylinder from A (0.3, -0.9) m to "
                   "the boom's eye 1 m out; the cylinder extends from 1.2 to 1.9 m in 4 s on a cycloidal law, the "
                   "boom tip is 2.8 m from O",
                   "cylinder rocker", makeCylinderRocker({}).value(), CycloidalRise{1.2, 0.7, 4.0}, 4.0, 201),
      linkageExample("stephenson-ii",
                     "Stephenson II six-bar (ground binary): its two ternary links close one loop with links 5 and 6, "
                     "a triad no dyad order solves, so C..E are found by Newton-Raphson",
                     "stephenson-ii", makeStephensonIINewton(kStephensonIINewton).value(), 2.0 * kPi),
      linkageExample("stephenson-iii-triad",
                     "Stephenson III six-bar driven from the link that is not in a four-bar loop: the floating "
                     "ternary C, D, E needs all three at once, so Newton-Raphson solves it",
                     "stephenson-iii-triad", makeStephensonIIINewton(kStephensonIIINewton).value(), 2.0 * kPi),
  };
}

std::optional<Example> findExample(const std::string& name) {
  for (Example& e : examples())
    if (e.name == name) return std::move(e);
  return std::nullopt;
}

}  // namespace linkwright::kinematics
