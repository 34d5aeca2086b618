#pragma once
// Linkages with masses and loads for the dynamics tests: one of each kind the core solves
// (four-bar, slider-crank, shaper with an RPR block, a dyad six-bar, the Newton-solved
// Stephenson II, a PRP yoke), with round-number properties chosen to exercise every term:
// centres off the link line, α2 ≠ 0, gravity, torques and forces on links and sliders; and
// the three examples driven along a path or by an actuator, on their time bases.

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <string>

namespace linkwright::test {

struct DynamicsCase {
  std::string name;
  kinematics::Mechanism mechanism;
  kinematics::LinkageDynamics dynamics;
  kinematics::SweepSpec spec;
};

/// A PRP "yoke": crank O2→B (20 mm); a block slides along the crank's line and is pinned at C
/// to a block in a vertical ground slot at x = 50 mm. C is where the two lines cross.
inline kinematics::Mechanism prpYoke() {
  using namespace kinematics;
  Mechanism m;
  m.points = {{"O2", GroundPoint{Eigen::Vector2d::Zero()}},
              {"B", CrankPoint{PointId{0}, 20.0, 0.0}},
              {"C", PrpPoint{Guide{LinkId{0}, Eigen::Vector2d::Zero(), 0.0},
                             Guide{std::nullopt, Eigen::Vector2d(50.0, 0.0), kPi / 2}}}};
  m.links = {{"crank", PointId{0}, PointId{1}}};
  return m;
}

inline std::vector<DynamicsCase> dynamicsCases() {
  using namespace kinematics;
  const Eigen::Vector2d g = standardGravity();
  const double turn = 2.0 * kPi;
  std::vector<DynamicsCase> cases;
  cases.push_back({"four-bar",
                   makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value(),
                   {{{"crank", 0.3, std::nullopt, std::nullopt},
                     {"coupler", 0.8, LinkFramePoint{30.0, 8.0}, 2e-3},
                     {"rocker", 0.5, LinkFramePoint{20.0, -3.0}, std::nullopt}},
                    {},
                    {g, {{"rocker", -2.0}}, {{"coupler", "P", 0, Eigen::Vector2d(5.0, -12.0)}}}},
                   {0.0, turn, 361, 10.0, 40.0}});
  cases.push_back({"slider-crank",
                   makeSliderCrank(kLs3Engine).value(),
                   {{{"crank", 1.2, LinkFramePoint{10.0, 0.0}, 1e-3}, {"rod", 0.6, std::nullopt, std::nullopt}},
                    {{"C", 0, 0.5, 0.0}},
                    {g, {}, {{"", "C", 0, Eigen::Vector2d(-3000.0, 0.0)}}}},
                   {0.0, turn, 361, turn * 50.0, 0.0}});
  cases.push_back({"shaper",
                   makeShaper(kSeedShaper).value(),
                   {{{"crank", 2.0, std::nullopt, std::nullopt},
                     {"rocker", 6.0, LinkFramePoint{200.0, 10.0}, std::nullopt},
                     {"link", 1.5, std::nullopt, 4e-3}},
                    {{"R", 0, 20.0, 0.0}, {"D", 0, 0.4, 1e-4}},
                    {g, {}, {{"", "R", 0, Eigen::Vector2d(-500.0, 0.0)}}}},
                   {0.0, turn, 361, turn * 3.0, 5.0}});
  cases.push_back({"watt-ii",
                   makeSixBar(kWattIISixBar).value(),
                   {{{"crank", 0.2, std::nullopt, std::nullopt},
                     {"coupler", 0.5, std::nullopt, std::nullopt},
                     {"rocker", 0.4, LinkFramePoint{30.0, 5.0}, std::nullopt},
                     {"link5", 0.3, std::nullopt, std::nullopt},
                     {"link6", 0.35, std::nullopt, std::nullopt}},
                    {},
                    {g, {{"link6", 1.5}}, {}}},
                   {0.0, turn, 361, turn, -3.0}});
  cases.push_back({"stephenson-ii",
                   makeStephensonIINewton().value(),
                   {{{"crank", 0.2, std::nullopt, std::nullopt},
                     {"coupler", 0.9, LinkFramePoint{60.0, -15.0}, 3e-3},
                     {"rocker", 0.7, LinkFramePoint{50.0, 20.0}, 2e-3},
                     {"link5", 0.1, std::nullopt, std::nullopt},
                     {"link6", 0.25, std::nullopt, std::nullopt}},
                    {},
                    {g, {{"rocker", 0.8}}, {{"coupler", "J3", 0, Eigen::Vector2d(0.0, -20.0)}}}},
                   {0.0, turn, 361, turn, 2.0}});
  cases.push_back({"prp-yoke",
                   prpYoke(),
                   {{{"crank", 0.2, std::nullopt, std::nullopt}},
                    {{"C", 0, 0.1, 1e-5}, {"C", 1, 0.3, 0.0}},
                    {g, {}, {{"", "C", 1, Eigen::Vector2d(0.0, -40.0)}}}},
                   {kinematics::degToRad(-60.0), kinematics::degToRad(60.0), 121, 30.0, 10.0}});
  return cases;
}

/// The linkages driven other than by a crank, with masses: seed 004's arm (upper 2 kg,
/// forearm 1.5 kg, centres at mid-link, a 20 N torch at the tip, in a vertical plane), the
/// piston-driven slider-crank (crank and rod masses, a 500 N load on the rod at the piston pin)
/// and the excavator boom (50 kg, its centre off the boom line, 2 kN at the tip), each on its
/// example's time base.
inline std::vector<DynamicsCase> drivenDynamicsCases() {
  using namespace kinematics;
  const Eigen::Vector2d g = standardGravity();
  std::vector<DynamicsCase> cases;
  const auto add = [&](const std::string& name, LinkageDynamics dynamics) {
    const Design d = *designForExample(name);
    cases.push_back({name, d.mechanism, std::move(dynamics), designSweepSpec(d)});
  };
  add("seed-arm", {{{"upper", 2.0, LinkFramePoint{0.15, 0.0}, 0.02}, {"forearm", 1.5, LinkFramePoint{0.1, 0.0}, 0.006}},
                   {},
                   {g, {}, {{"forearm", "tip", 0, Eigen::Vector2d(0.0, -20.0)}}}});
  add("piston-driven", {{{"crank", 0.5, std::nullopt, std::nullopt}, {"rod", 0.8, LinkFramePoint{50.0, 2.0}, 2e-3}},
                        {},
                        {g, {{"crank", -3.0}}, {{"rod", "C", 0, Eigen::Vector2d(-500.0, 0.0)}}}});
  add("excavator-boom", {{{"boom", 50.0, LinkFramePoint{1.4, 0.05}, 30.0}},
                         {},
                         {g, {}, {{"boom", "tip", 0, Eigen::Vector2d(0.0, -2000.0)}}}});
  return cases;
}

/// Sample j of a sweep as a pose (positions, rates, link angles and rates).
inline kinematics::Pose poseAt(const kinematics::Mechanism& m, const kinematics::SweepResult& s, std::size_t j) {
  kinematics::Pose p;
  kinematics::preparePose(m, p);
  kinematics::copySampleToPose(s, j, p);
  return p;
}

}  // namespace linkwright::test
