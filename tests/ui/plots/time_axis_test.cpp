// The plots on a time base (ui/plots/plot_x_axis.h, and what plot_panel, limit_markers and
// hover_readout make of it): x is the sweep's time, or the input angle, as the document's
// plotAxis() says; limit positions sit where the law passes them; the cursor follows the instant.

#include "ui/plots/plot_panel.h"
#include "ui/plots/plot_x_axis.h"

#include "four_bar_curves.h"
#include "plotted_points.h"

#include "ui/plots/hover_readout.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/quantity_chart_view.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/timed_design.h"

#include <QLineSeries>
#include <QValueAxis>

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::ui;
using linkwright::ui::test::fourBarCurve;
using linkwright::ui::test::plotted;
namespace k = linkwright::kinematics;
namespace testing = linkwright::testing;

TEST_CASE("on a time base the series' x are the sweep's times, or its input angles in degrees", "[ui][plots][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  PlotPanel plots(&doc);
  const k::SweepResult& s = doc.sweep();
  const std::size_t rocker = k::fourbar::kRocker.index;
  REQUIRE(s.size() > 2);
  REQUIRE(doc.plotAxis() == PlotAxis::Time);

  // The crank-rocker turns fully: every sample is plotted, in sweep order.
  QList<QPointF> points = plotted(plots, PlotQuantity::RockerAngle);
  REQUIRE(points.size() == static_cast<qsizetype>(s.size()));
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(j);
    CHECK(points[static_cast<qsizetype>(j)].x() == s.time[j]);
    CHECK(points[static_cast<qsizetype>(j)].y() == k::radToDeg(s.linkAngle[rocker][j]));
  }
  CHECK(points.back().x() == testing::kRiseDuration);  // the law's end time
  QuantityChartView* angles = plots.chartView(QuantityKind::Angle);
  CHECK(angles->xAxis()->titleText() == "time [s]");
  CHECK(angles->xAxis()->min() == 0.0);
  CHECK(angles->xAxis()->max() == testing::kRiseDuration);

  doc.setPlotAxis(PlotAxis::Input);
  points = plotted(plots, PlotQuantity::RockerOmega);
  REQUIRE(points.size() == static_cast<qsizetype>(s.size()));
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(j);
    CHECK(points[static_cast<qsizetype>(j)].x() == k::radToDeg(s.inputAngle[j]));
  }
  CHECK(points.back().x() == Approx(360.0).margin(1e-12));  // the rise's end
  CHECK(plots.chartView(QuantityKind::Omega)->xAxis()->titleText() == "crank angle [deg]");
}

TEST_CASE("on a time base the rocker's limits are marked at the instants the crank passes them", "[ui][plots][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  PlotPanel plots(&doc);
  const k::LimitReport& limits = doc.analysis().limits;
  REQUIRE(limits.positions.size() == 2);
  const k::TimeBase& time = *doc.design().time;
  // One turn: each limit once, at the instant where the law's angle is the limit's crank angle.
  const QList<double> xs = plots.limitMarkers()->lineXs();
  REQUIRE(xs.size() == 2);
  for (qsizetype i = 0; i < 2; ++i) {
    CAPTURE(i);
    CHECK(xs[i] > 0.0);
    CHECK(xs[i] < testing::kRiseDuration);
    CHECK(k::motionAt(time.law, xs[i]).position ==
          Approx(limits.positions[static_cast<std::size_t>(i)].crankAngle).margin(1e-12));
  }
  CHECK(plots.limitNote().isEmpty());

  doc.setPlotAxis(PlotAxis::Input);
  const QList<double> degrees = plots.limitMarkers()->lineXs();
  REQUIRE(degrees.size() == 2);
  for (qsizetype i = 0; i < 2; ++i)
    CHECK(degrees[i] == Approx(k::radToDeg(limits.positions[static_cast<std::size_t>(i)].crankAngle)).margin(1e-9));
}

TEST_CASE("limits passed too often to read are not marked, and a note says why", "[ui][plots][law]") {
  MechanismDocument doc;
  doc.reset(testing::longRampFourBar());  // about a hundred turns: two hundred limit crossings
  PlotPanel plots(&doc);
  plots.show();
  CHECK(plots.limitMarkers()->lineXs().isEmpty());
  CHECK(plots.limitNote().contains("not marked"));
  CHECK(plots.limitNote().contains("48"));
}

TEST_CASE("the cursor follows the instant on a time axis, the crank angle on the input axis", "[ui][plots][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  PlotPanel plots(&doc);
  doc.setTime(0.3);
  CHECK(plots.chartView(QuantityKind::Angle)->cursorX() == 0.3);
  doc.setPlotAxis(PlotAxis::Input);
  CHECK(plots.chartView(QuantityKind::Angle)->cursorX() == Approx(k::radToDeg(doc.crankAngle())));
}

TEST_CASE("x axis titles and read-outs name the time or the input", "[ui][plots][law]") {
  const k::Mechanism fourBar = testing::fourBar().mechanism;
  CHECK(inputAxisTitle(fourBar, AngleUnit::Degrees) == "crank angle [deg]");
  CHECK(inputAxisTitle(fourBar, AngleUnit::Radians) == "crank angle [rad]");
  CHECK(timeAxisTitle() == "time [s]");
  PlotXAxis time;
  time.source.axis = PlotAxis::Time;
  CHECK(readoutText(fourBarCurve(PlotQuantity::RockerOmega), {0.25, 35.47}, AngleUnit::Degrees, "mm", time) ==
        "rocker ω4 = 35.5 deg/s at t = 0.250 s");
  const AxisRange r = exactAxisRange(0.0, 0.5);
  CHECK(r.min == 0.0);
  CHECK(r.max == 0.5);
  CHECK(r.step == 0.2);
  CHECK(r.tickCount == 3);
}
