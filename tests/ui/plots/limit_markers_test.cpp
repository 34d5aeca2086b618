// Tests ui/plots/limit_markers.h: where the rocker's limit positions land on the angle chart.
#include "ui/plots/limit_markers.h"

#include "kinematics/analysis/limit_positions.h"
#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

struct Solved {
  k::Design design;
  k::SweepResult sweep;
  k::LimitReport limits;
};

Solved solve(const k::Design& design) {
  const auto fourBar = k::asFourBar(design.mechanism).value();
  return {design, k::sweep(design.mechanism, k::designSweepSpec(design)).value(),
          k::fourBarLimitPositions(fourBar.lengths, fourBar.branch)};
}

}  // namespace

TEST_CASE("Limit markers of the thesis crank-rocker sit at 21.59° and 228.19°", "[limit_markers]") {
  const Solved s = solve(linkwright::testing::fourBar());  // 60, 25, 70, 45 mm, open
  const QList<QPointF> points = limitMarkerPoints(s.limits, s.sweep, 0.0, 360.0, AngleUnit::Degrees);
  REQUIRE(points.size() == 2);
  // The thesis prints two decimals.
  CHECK(points[0].x() == Approx(21.59).margin(0.005));
  CHECK(points[1].x() == Approx(228.19).margin(0.005));
  // On the rocker curve: within what the rocker turns in half a grid step (0.25°) of crank.
  const std::size_t rocker = k::fourbar::kRocker.index;
  for (const QPointF& p : points) {
    const auto j = static_cast<std::size_t>(std::lround(p.x() / 0.5));
    CHECK(p.y() == Approx(k::radToDeg(s.sweep.linkAngle[rocker][j])).margin(0.25));
  }
}

TEST_CASE("Limit markers follow the unit and leave out limits outside the grid", "[limit_markers]") {
  const Solved s = solve(linkwright::testing::fourBar());
  const QList<QPointF> rad = limitMarkerPoints(s.limits, s.sweep, 0.0, 360.0, AngleUnit::Radians);
  REQUIRE(rad.size() == 2);
  CHECK(rad[0].x() == Approx(s.limits.positions[0].crankAngle));
  k::Design part = linkwright::testing::fourBar();
  part.fromDeg = 0.0;
  part.toDeg = 180.0;
  part.samples = 361;
  const Solved half = solve(part);
  const QList<QPointF> points = limitMarkerPoints(half.limits, half.sweep, 0.0, 180.0, AngleUnit::Degrees);
  REQUIRE(points.size() == 1);
  CHECK(points[0].x() == Approx(21.59).margin(0.005));
}
