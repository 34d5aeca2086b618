// The animator (ui/animation/crank_animator.h) on a time base: it runs the law's clock, so the
// document visits the instants in time order at real time, then starts over (or stops).

#include "ui/animation/crank_animator.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/timed_design.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright;
namespace k = kinematics;

TEST_CASE("on a time base the animator visits the sweep's samples in time order, then loops", "[ui][animation][law]") {
  ui::MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  const k::SweepResult& s = doc.sweep();
  const std::size_t n = s.size();
  REQUIRE(n > 10);
  ui::CrankAnimator animator(&doc);
  // One frame per sample interval: frame j shows sample j, the law's state at its time.
  const double dt = testing::kRiseDuration / static_cast<double>(n - 1);
  const std::size_t rocker = k::fourbar::kRocker.index;
  for (std::size_t j = 1; j < n; ++j) {
    animator.advance(dt);
    CAPTURE(j);
    REQUIRE(doc.time() == Approx(s.time[j]).margin(1e-12));
    CHECK(doc.crankAngle() == Approx(s.inputAngle[j]).margin(1e-9));
    // Same rocker as the plotted sample (the sweep's angle is unwrapped, the pose's is not).
    CHECK(std::remainder(doc.pose().linkAngle[rocker] - s.linkAngle[rocker][j], 2.0 * k::kPi) ==
          Approx(0.0).margin(1e-7));
  }
  CHECK(doc.time() == Approx(testing::kRiseDuration).margin(1e-12));
  // Past the end it goes on from the start by what is left.
  animator.advance(0.1);
  CHECK(doc.time() == Approx(0.1).margin(1e-9));
  CHECK(animator.direction() == 1);
}

TEST_CASE("without looping the animator stops at the time base's end, and plays again from its start",
          "[ui][animation][law]") {
  ui::MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  ui::CrankAnimator animator(&doc);
  animator.setLooping(false);
  animator.play();
  double last = doc.time();
  for (int frame = 0; frame < 100 && animator.isPlaying(); ++frame) {
    animator.advance(0.016);
    CHECK(doc.time() > last);
    last = doc.time();
  }
  CHECK_FALSE(animator.isPlaying());
  CHECK(doc.time() == testing::kRiseDuration);
  animator.play();
  CHECK(doc.time() == 0.0);
  animator.pause();
}

TEST_CASE("on a time base a step moves the instant by the step time", "[ui][animation][law]") {
  ui::MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  ui::CrankAnimator animator(&doc);
  animator.setStepTime(0.2);
  animator.stepForward();
  CHECK(doc.time() == Approx(0.2));
  animator.stepForward();
  animator.stepForward();
  CHECK(doc.time() == testing::kRiseDuration);  // clamped at the end
  animator.stepBackward();
  CHECK(doc.time() == Approx(0.3));
}
