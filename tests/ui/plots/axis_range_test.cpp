// Tests ui/plots/axis_range.h: rounded value ranges, the crank axis, wrapping into the grid.
#include "ui/plots/axis_range.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::ui;

namespace {

bool isMultipleOf(double value, double step) {
  const double q = value / step;
  return std::abs(q - std::round(q)) < 1e-9;
}

}  // namespace

TEST_CASE("niceStep rounds up to 1, 2, 2.5 or 5 times a power of ten", "[axis_range]") {
  CHECK(niceStep(0.7) == Approx(1.0));
  CHECK(niceStep(1.3) == Approx(2.0));
  CHECK(niceStep(2.2) == Approx(2.5));
  CHECK(niceStep(3.0) == Approx(5.0));
  CHECK(niceStep(7.0) == Approx(10.0));
  CHECK(niceStep(0.02) == Approx(0.02));
  CHECK(niceStep(430.0) == Approx(500.0));
}

TEST_CASE("decimalsFor prints the step exactly", "[axis_range]") {
  CHECK(decimalsFor(10.0) == 0);
  CHECK(decimalsFor(2.5) == 1);
  CHECK(decimalsFor(0.25) == 2);
  CHECK(decimalsFor(0.05) == 2);
}

TEST_CASE("niceValueRange holds the data with a margin, on rounded bounds", "[axis_range]") {
  const double lo = GENERATE(-3.7, 0.0, 12.3, -1234.5);
  const double span = GENERATE(0.013, 1.0, 77.0, 5000.0);
  const double hi = lo + span;
  CAPTURE(lo, hi);
  const AxisRange r = niceValueRange(lo, hi);
  CHECK(r.min < lo);  // a margin each side: no curve touches the frame
  CHECK(r.max > hi);
  CHECK(isMultipleOf(r.min, r.step));
  CHECK(isMultipleOf(r.max, r.step));
  CHECK(r.tickCount == static_cast<int>(std::lround((r.max - r.min) / r.step)) + 1);
  CHECK(r.tickCount >= 3);
  CHECK(r.tickCount <= 7);
  // Not much wider than needed: the data fills at least a third of the axis.
  CHECK(span / (r.max - r.min) > 1.0 / 3.0);
}

TEST_CASE("niceValueRange widens a flat series and survives no data", "[axis_range]") {
  const AxisRange one = niceValueRange(1.0, 1.0);
  CHECK(one.min < 1.0);
  CHECK(one.max > 1.0);
  CHECK(one.max - one.min <= 0.5);
  const AxisRange zero = niceValueRange(0.0, 0.0);
  CHECK(zero.min <= -1.0);
  CHECK(zero.max >= 1.0);
  const AxisRange none = niceValueRange(INFINITY, -INFINITY);
  CHECK(none.min == 0.0);
  CHECK(none.max == 1.0);
}

TEST_CASE("robustSpan keeps a smooth curve whole and lets toggle spikes run off", "[axis_range]") {
  std::vector<double> smooth;
  for (int i = 0; i <= 720; ++i) smooth.push_back(std::sin(0.5 * i * linkwright::kinematics::kPi / 180.0));
  const auto [lo, hi] = robustSpan(smooth);
  CHECK(lo == Approx(-1.0));
  CHECK(hi == Approx(1.0));

  std::vector<double> spiky = {0.0,  1.0,  2.0,  3.0,  4.0,  5.0,  6.0,  7.0,  8.0,  9.0,  10.0,
                               11.0, 12.0, 13.0, 14.0, 15.0, 16.0, 17.0, 18.0, 19.0, 20.0, 5000.0};
  const auto [slo, shi] = robustSpan(spiky);
  CHECK(slo == 0.0);
  CHECK(shi < 50.0);   // the spike runs off the chart
  CHECK(shi >= 20.0);  // the bulk stays on it
}

TEST_CASE("The crank axis covers the grid exactly with readable ticks", "[axis_range]") {
  const AxisRange full = crankAxisRange(0.0, 360.0, AngleUnit::Degrees);
  CHECK(full.min == 0.0);
  CHECK(full.max == 360.0);
  CHECK(full.step == 90.0);
  CHECK(full.tickCount == 5);
  CHECK(full.decimals == 0);

  const AxisRange part = crankAxisRange(-30.0, 60.0, AngleUnit::Degrees);
  CHECK(part.step == 30.0);

  const AxisRange rad = crankAxisRange(0.0, 360.0, AngleUnit::Radians);
  CHECK(rad.min == 0.0);
  CHECK(rad.max == Approx(2.0 * linkwright::kinematics::kPi));
  CHECK(rad.step == Approx(2.0));
  CHECK(rad.tickCount == 4);
}

TEST_CASE("wrapIntoRange moves an angle by whole turns into the grid", "[axis_range]") {
  CHECK(*wrapIntoRange(90.0, 0.0, 360.0) == Approx(90.0));
  CHECK(*wrapIntoRange(-90.0, 0.0, 360.0) == Approx(270.0));
  CHECK(*wrapIntoRange(450.0, 0.0, 360.0) == Approx(90.0));
  CHECK(*wrapIntoRange(200.0, -180.0, 180.0) == Approx(-160.0));
  CHECK(*wrapIntoRange(360.0, 0.0, 360.0) == Approx(0.0));
  CHECK(*wrapIntoRange(359.9999999999999, 0.0, 360.0) == Approx(0.0).margin(1e-9));
  CHECK(*wrapIntoRange(30.0, 10.0, 50.0) == Approx(30.0));
  CHECK_FALSE(wrapIntoRange(90.0, 10.0, 50.0).has_value());
}

TEST_CASE("keepsRange keeps an axis that still holds the data and is at least half filled", "[axis_range]") {
  const AxisRange shown = niceValueRange(10.0, 90.0);  // [0, 100]
  REQUIRE(shown.min == 0.0);
  REQUIRE(shown.max == 100.0);
  CHECK(keepsRange(shown, 10.0, 90.0));
  CHECK(keepsRange(shown, 0.0, 50.0));         // exactly half
  CHECK_FALSE(keepsRange(shown, 10.0, 45.0));  // less than half: fit the data again
  CHECK_FALSE(keepsRange(shown, -1.0, 90.0));  // off the axis
  CHECK_FALSE(keepsRange(shown, 10.0, 100.5));
  CHECK_FALSE(keepsRange(shown, 90.0, 10.0));  // no data
  CHECK_FALSE(keepsRange(shown, std::nan(""), 90.0));
  CHECK_FALSE(keepsRange(AxisRange{5.0, 5.0}, 5.0, 5.0));  // an empty axis serves nothing
}

TEST_CASE("refittedRange fits settled data tightly and leaves changing data room to grow", "[axis_range]") {
  const auto [lo, hi] = GENERATE(table<double, double>({{10.0, 90.0}, {-3.2, 7.9}, {0.0012, 0.0047}, {-250.0, -40.0}}));
  CAPTURE(lo, hi);
  CHECK(refittedRange(lo, hi, DataFlow::Settled) == niceValueRange(lo, hi));
  const AxisRange roomy = refittedRange(lo, hi, DataFlow::Changing);
  CAPTURE(roomy.min, roomy.max);
  const double span = hi - lo;
  // Kept for these data, and for the next frames of a drag that move them a twentieth of their
  // span further than niceValueRange's margin would hold.
  CHECK(keepsRange(roomy, lo, hi));
  CHECK(keepsRange(roomy, lo - 0.1 * span, hi + 0.1 * span));
  // Flat or missing data have no span to leave room for.
  CHECK(refittedRange(10.0, 90.0, DataFlow::Changing) != niceValueRange(10.0, 90.0));  // [-25, 125], not [0, 100]
  CHECK(refittedRange(5.0, 5.0, DataFlow::Changing) == niceValueRange(5.0, 5.0));
  CHECK(refittedRange(std::nan(""), 1.0, DataFlow::Changing) == AxisRange{});
}
