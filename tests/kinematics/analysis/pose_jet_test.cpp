// The differentiated pose (kinematics/analysis/pose_jet.h) carries the solver's own motion:
// its values, rates and accelerations are the pose solver's (which differentiates the loop
// equations instead) to round-off, on every kind of linkage the examples hold; and it refuses
// a stepped mechanism of another structure.

#include "kinematics/analysis/pose_jet.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("the jets' values, rates and accelerations are the pose solver's", "[tolerance][jet]") {
  for (const Example& e : examples()) {
    const Mechanism& m = e.mechanism;
    const bool linear = inputKind(m) == InputKind::Length;
    for (const double at : {0.15, 0.4, 0.7}) {
      // A linear driver inside its example's range, a crank anywhere on the turn.
      const double q = linear ? e.fromDeg + at * (e.toDeg - e.fromDeg) : degToRad(360.0 * at + 7.0);
      const DriverState driver{q, linear ? 0.3 : 2.0, linear ? -0.2 : 5.0};
      const auto pose = solvePose(m, driver);
      if (!pose) continue;
      PoseJet jet;
      INFO(e.name << " at " << q);
      REQUIRE(differentiatePose(m, m, driver, pose->position, jet));
      double size = 1.0;
      for (const auto& p : pose->position) size = std::max(size, p.norm());
      for (std::size_t i = 0; i < m.points.size(); ++i) {
        CHECK(jet.position[i].x.value() == Approx(pose->position[i].x()).margin(1e-10 * size));
        CHECK(jet.position[i].y.value() == Approx(pose->position[i].y()).margin(1e-10 * size));
        CHECK(jet.position[i].x.rate() == Approx(pose->velocity[i].x()).margin(1e-9 * size));
        CHECK(jet.position[i].y.rate() == Approx(pose->velocity[i].y()).margin(1e-9 * size));
        CHECK(jet.position[i].x.acceleration() == Approx(pose->acceleration[i].x()).margin(1e-8 * size));
        CHECK(jet.position[i].y.acceleration() == Approx(pose->acceleration[i].y()).margin(1e-8 * size));
        // The same linkage as its own step: every derivative is zero.
        CHECK(jet.position[i].x.valueSensitivity() == 0.0);
        CHECK(jet.position[i].y.accelerationSensitivity() == 0.0);
      }
      for (std::size_t k = 0; k < m.links.size(); ++k) {
        CHECK(std::remainder(jet.linkAngle[k].value() - pose->linkAngle[k], 2 * kPi) == Approx(0.0).margin(1e-10));
        CHECK(jet.linkAngle[k].rate() == Approx(pose->linkOmega[k]).margin(1e-9));
        CHECK(jet.linkAngle[k].acceleration() == Approx(pose->linkAlpha[k]).margin(1e-7));
      }
    }
  }
}

TEST_CASE("a stepped mechanism of another structure is refused", "[tolerance][jet]") {
  const Mechanism m = findExample("thesis-crank-rocker")->mechanism;
  Mechanism other = m;
  other.points.pop_back();
  const Pose pose = solvePose(m, DriverState{0.3, 1.0, 0.0}).value();
  PoseJet jet;
  CHECK_FALSE(differentiatePose(m, other, DriverState{0.3, 1.0, 0.0}, pose.position, jet));
  CHECK(differentiatePose(m, m, DriverState{0.3, 1.0, 0.0}, pose.position, jet));
}
