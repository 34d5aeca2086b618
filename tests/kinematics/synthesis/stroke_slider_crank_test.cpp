// Tests kinematics/synthesis/stroke_slider_crank.h: the synthesised slider-crank, solved by the
// pose solver (not by the synthesis), has its slider at rest exactly twice a turn, the given
// stroke between those ends and the given time ratio, to 1e-9; Q = 1 gives the in-line
// slider-crank with the crank half the stroke; bad targets name the field; a published exam
// problem's offset slider-crank (GATE 2025) comes back from its stroke and time ratio.

#include "kinematics/synthesis/stroke_slider_crank.h"

#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::within;

namespace {

// The slider's velocity along the guide at crank angle θ, ω = 1.
double sliderSpeed(const Mechanism& m, double theta) {
  const auto pose = solvePose(m, {theta, 1.0, 0.0}, {true, false});
  REQUIRE(pose.ok());
  return pose->velocity[slidercrank::kC.index].x();
}

struct Ends {
  std::vector<double> crankAngles;  // where the slider stops
  double stroke = 0.0;
  double timeRatio = 0.0;
};

// The slider's dead centres, found by bisection on its velocity's sign changes over a 0.1°
// grid, then the stroke between them and the crank arcs' ratio.
Ends solvedEnds(const Mechanism& m) {
  Ends ends;
  const int n = 3600;
  double previous = sliderSpeed(m, 0.0);
  for (int k = 1; k <= n; ++k) {
    double lo = 2.0 * kPi * (k - 1) / n, hi = 2.0 * kPi * k / n;
    const double v = sliderSpeed(m, hi);
    if ((previous < 0.0) != (v < 0.0)) {
      const bool rising = previous < 0.0;
      for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((sliderSpeed(m, mid) < 0.0) == rising ? lo : hi) = mid;
      }
      ends.crankAngles.push_back(0.5 * (lo + hi));
    }
    previous = v;
  }
  if (ends.crankAngles.size() != 2) return ends;
  const auto x = [&](double theta) {
    return solvePose(m, {theta, 0.0, 0.0}, {false, false})->position[slidercrank::kC.index].x();
  };
  ends.stroke = std::abs(x(ends.crankAngles[1]) - x(ends.crankAngles[0]));
  const double arc = ends.crankAngles[1] - ends.crankAngles[0];
  ends.timeRatio = std::max(arc, 2.0 * kPi - arc) / std::min(arc, 2.0 * kPi - arc);
  return ends;
}

}  // namespace

TEST_CASE("The synthesised slider-crank has the target stroke and time ratio", "[synthesis][slider]") {
  const auto [stroke, timeRatio, rodOrOffset, byRod] = GENERATE(table<double, double, double, bool>({
      {100.0, 1.0, 150.0, true},
      {100.0, 1.2, 150.0, true},
      {100.0, 1.5, 90.0, true},
      {50.0, 1.1, 10.0, false},
      {50.0, 1.3, -10.0, false},
      {80.0, 1.25, 30.0, false},
  }));
  CAPTURE(stroke, timeRatio, rodOrOffset, byRod);
  const StrokeTarget target{stroke, timeRatio, byRod ? SliderChoice::Rod : SliderChoice::Offset, rodOrOffset};
  const auto s = synthesiseSliderCrank(target);
  REQUIRE(s.ok());
  if (byRod) CHECK(s->geometry.rod == rodOrOffset);
  else CHECK(s->geometry.offset == within(rodOrOffset, 1e-12));
  REQUIRE(asSliderCrank(s->candidate.design.mechanism).has_value());
  const Ends ends = solvedEnds(s->candidate.design.mechanism);
  REQUIRE(ends.crankAngles.size() == 2);
  // Bisection pins the dead centres to 1e-15 rad, where the slider's position is stationary,
  // so the stroke and ratio are good to round-off: 1e-9 is the task's bound.
  CHECK(ends.stroke == within(stroke, 1e-9 * stroke));
  CHECK(ends.timeRatio == within(timeRatio, 1e-9));
  // The construction's dead-centre crank angles are the solver's (a crossing found on a grid
  // is within 1e-12 rad of the true one once velocity round-off is allowed for).
  for (const double theta : ends.crankAngles)
    CHECK(std::min(std::abs(angleDifference(theta, s->extendedCrankAngle)),
                   std::abs(angleDifference(theta, s->foldedCrankAngle))) < 1e-9);
  CHECK(s->farEnd - s->nearEnd == within(stroke, 1e-12 * stroke));
  CHECK(s->candidate.error == 0.0);
}

TEST_CASE("Time ratio 1 gives the in-line slider-crank", "[synthesis][slider]") {
  const auto s = synthesiseSliderCrank({120.0, 1.0, SliderChoice::Rod, 200.0});
  REQUIRE(s.ok());
  CHECK(s->geometry.offset == 0.0);
  CHECK(s->geometry.crank == within(60.0, 1e-12));  // half the stroke
  // The rod is steepest with the crank square to the guide: sin β = a / b = 0.3.
  CHECK(s->candidate.minTransmission == within(kPi / 2.0 - std::asin(0.3), 1e-15));
}

TEST_CASE("The slider-crank's worst transmission matches a fine sweep", "[synthesis][slider]") {
  const auto s = synthesiseSliderCrank({100.0, 1.3, SliderChoice::Offset, 20.0});
  REQUIRE(s.ok());
  const auto sw = sweep(s->candidate.design.mechanism, {0.0, 2.0 * kPi, 7201, 1.0, 0.0});
  REQUIRE(sw.ok());
  const auto& mu = sw->transmissionAngle[slidercrank::kC.index];
  const double sampled = *std::min_element(mu.begin(), mu.end());
  CHECK(sampled >= s->candidate.minTransmission - 1e-12);
  CHECK(sampled <= s->candidate.minTransmission + 1e-4);  // a 0.05° grid near a smooth minimum
}

TEST_CASE("Bad stroke targets are errors naming the field", "[synthesis][slider][errors]") {
  const auto [stroke, timeRatio, value, byRod, field] = GENERATE(table<double, double, double, bool, std::string>({
      {0.0, 1.2, 100.0, true, "stroke"},
      {-5.0, 1.2, 100.0, true, "stroke"},
      {100.0, 0.5, 100.0, true, "timeRatio"},
      {100.0, std::nan(""), 100.0, true, "timeRatio"},
      {100.0, 1.2, 40.0, true, "rod"},    // shorter than half the stroke
      {100.0, 1.5, 1000.0, true, "rod"},  // longer than H / (2 sin(α/2))
      {100.0, 1.2, std::nan(""), true, "rod"},
      {100.0, 1.0, 5.0, false, "offset"},  // Q = 1 needs no offset
      {100.0, 1.2, 1e4, false, "offset"},  // past H / (2 tan(α/2))
      {100.0, 1.2, INFINITY, false, "offset"},
  }));
  CAPTURE(stroke, timeRatio, value, byRod);
  const auto s = synthesiseSliderCrank({stroke, timeRatio, byRod ? SliderChoice::Rod : SliderChoice::Offset, value});
  REQUIRE_FALSE(s.ok());
  CHECK(s.error().field == field);
  CHECK_FALSE(s.error().message.empty());
}

TEST_CASE("Published example: the GATE 2025 offset slider-crank (crank 30, rod 50, offset 10 mm)",
          "[synthesis][slider][published]") {
  // GATE 2025 Mechanical Engineering, the offset slider-crank stroke question, in the worked
  // solution at examprev.com/question/mechanical-engineering-gate-2025-question-60: crank
  // r = 30 mm, rod l = 50 mm, offset e = 10 mm; the slider's ends at sqrt((r + l)² − e²) =
  // sqrt(6300) = 79.37 mm and sqrt((l − r)² − e²) = sqrt(300) = 17.32 mm from the crank pivot's
  // foot on the guide, stroke 62.05 ≈ 62 mm. This is the analysis direction: we give
  // Linkwright the printed stroke (its exact form) with the rod, and the example's time ratio,
  // which it does not print, from its dimensions: the crank turns 180° + α from end to end
  // with α = asin(e / (l − r)) − asin(e / (l + r)) = 30° − 7.18°. The synthesis must give
  // back the crank and offset exactly, and the printed ends to their two decimals.
  const double r = 30.0, l = 50.0, e = 10.0;
  const double stroke = std::sqrt(6300.0) - std::sqrt(300.0);
  const double alpha = std::asin(e / (l - r)) - std::asin(e / (l + r));
  const double timeRatio = (kPi + alpha) / (kPi - alpha);
  const auto s = synthesiseSliderCrank({stroke, timeRatio, SliderChoice::Rod, l});
  REQUIRE(s.ok());
  CHECK(s->geometry.crank == within(r, 1e-9));
  CHECK(s->geometry.offset == within(e, 1e-9));
  CHECK(s->nearEnd == within(17.32, 0.005));
  CHECK(s->farEnd == within(79.37, 0.005));
  CHECK(s->farEnd - s->nearEnd == within(62.05, 0.005));
  // The other free choice, the offset, gives the rod back.
  const auto byOffset = synthesiseSliderCrank({stroke, timeRatio, SliderChoice::Offset, e});
  REQUIRE(byOffset.ok());
  CHECK(byOffset->geometry.crank == within(r, 1e-9));
  CHECK(byOffset->geometry.rod == within(l, 1e-9));
  // Checked by the pose solver, not the synthesis: the slider stops at the printed stroke
  // (to its two decimals) and the crank arcs between the stops have the example's ratio.
  const Ends ends = solvedEnds(s->candidate.design.mechanism);
  REQUIRE(ends.crankAngles.size() == 2);
  CHECK(ends.stroke == within(62.05, 0.005));
  CHECK(ends.timeRatio == within(timeRatio, 1e-9));
}
