// Tests ui/plots/plot_panel.h offscreen: what the charts plot against the document's sweep,
// the request the checkboxes make, units, gaps, the cursor, limit markers and hover read-out.
#include "ui/plots/plot_panel.h"

#include "four_bar_curves.h"
#include "mouse_on_curve.h"
#include "plotted_points.h"

#include "ui/plots/hover_readout.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include "kinematics/design/dyad_request.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QCoreApplication>
#include <QImage>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QValueAxis>

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <memory>

using namespace linkwright::ui;
using linkwright::ui::test::fourBarCurve;
using linkwright::ui::test::fourBarQuantities;
using linkwright::ui::test::plotted;
namespace k = linkwright::kinematics;

namespace {

// What the sweep says should be plotted, written out from its documented contract:
// positions where assembled, rates where ok, x the crank angle, all in degrees.
QList<QPointF> expectedDegrees(const k::SweepResult& s, const std::vector<double>& column, bool rate) {
  QList<QPointF> points;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (rate ? s.ok(j) : s.assembled(j)) points.append({k::radToDeg(s.inputAngle[j]), k::radToDeg(column[j])});
  return points;
}

void tick(PlotPanel& panel, PlotQuantity q, bool on) { panel.selector()->checkBox(q)->setChecked(on); }

k::Design nonGrashof() { return linkwright::testing::fourBar({40.0, 30.0, 20.0, 25.0}); }

constexpr std::size_t kCoupler = k::fourbar::kCoupler.index;
constexpr std::size_t kRocker = k::fourbar::kRocker.index;

}  // namespace

TEST_CASE("After construction the series hold the document's sweep", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  const k::SweepResult& s = doc.sweep();

  const QList<QPointF> coupler = plotted(panel, PlotQuantity::CouplerAngle);
  REQUIRE(coupler.size() == static_cast<qsizetype>(s.size()));  // a crank-rocker assembles everywhere
  for (std::size_t j : {std::size_t{0}, std::size_t{90}, std::size_t{333}, std::size_t{720}}) {
    CAPTURE(j);
    const auto i = static_cast<qsizetype>(j);
    CHECK(coupler[i].x() == k::radToDeg(s.inputAngle[j]));
    CHECK(coupler[i].y() == k::radToDeg(s.linkAngle[kCoupler][j]));
    CHECK(plotted(panel, PlotQuantity::RockerOmega)[i].y() == k::radToDeg(s.linkOmega[kRocker][j]));
    CHECK(plotted(panel, PlotQuantity::RockerAlpha)[i].y() == k::radToDeg(s.linkAlpha[kRocker][j]));
    CHECK(plotted(panel, PlotQuantity::TransmissionAngle)[i].y() ==
          k::radToDeg(s.transmissionAngle[k::fourbar::kC.index][j]));
  }
  qsizetype okSamples = 0;
  for (std::size_t j = 0; j < s.size(); ++j) okSamples += s.ok(j) ? 1 : 0;
  CHECK(plotted(panel, PlotQuantity::CouplerOmega).size() == okSamples);
  CHECK(plotted(panel, PlotQuantity::CouplerAlpha).size() == okSamples);
  CHECK(plotted(panel, PlotQuantity::RockerOmega) == expectedDegrees(s, s.linkOmega[kRocker], true));

  // Axes: the x axis is the grid, the y axis holds every point.
  const QuantityChartView* angles = panel.chartView(QuantityKind::Angle);
  CHECK(angles->xAxis()->min() == 0.0);
  CHECK(angles->xAxis()->max() == 360.0);
  for (const QPointF& p : coupler) {
    CHECK(p.y() > angles->yAxis()->min());
    CHECK(p.y() < angles->yAxis()->max());
  }
  CHECK(angles->xAxis()->titleText() == QStringLiteral("crank angle [deg]"));
  CHECK(angles->yAxis()->titleText() == QStringLiteral("angle [deg]"));
  CHECK(panel.chartView(QuantityKind::Omega)->yAxis()->titleText() == QStringLiteral("ω [deg/s]"));
  CHECK(panel.chartViews().size() == 8);  // a four-bar has no slider: its three charts are hidden
  // (and the ratios' two, until asked for)
  for (const auto kind : {QuantityKind::Position, QuantityKind::Velocity, QuantityKind::Acceleration,
                          QuantityKind::VelocityRatio, QuantityKind::Advantage})
    CHECK(panel.chartView(kind)->isHidden());
  CHECK(panel.chartTitle(1) == QStringLiteral("Angular velocities"));
  CHECK(panel.chartViews()[1]->chart()->title() == panel.chartTitle(1));
}

TEST_CASE("Editing a length re-plots what the core now says", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  const QList<QPointF> before = plotted(panel, PlotQuantity::RockerAngle);
  const k::Design d = linkwright::testing::withLengths(doc.design(), {60.0, 25.0, 65.0, 45.0});
  REQUIRE_FALSE(doc.edit(d, QStringLiteral("coupler")).has_value());
  const QList<QPointF> after = plotted(panel, PlotQuantity::RockerAngle);
  CHECK(after != before);
  CHECK(after == expectedDegrees(doc.sweep(), doc.sweep().linkAngle[kRocker], false));
  CHECK(plotted(panel, PlotQuantity::CouplerOmega) ==
        expectedDegrees(doc.sweep(), doc.sweep().linkOmega[kCoupler], true));
  doc.undoStack()->undo();
  CHECK(plotted(panel, PlotQuantity::RockerAngle) == before);
}

TEST_CASE("The checkboxes request only what is shown and hide empty charts", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  QSignalSpy selectionSpy(&panel, &PlotPanel::selectionChanged);
  CHECK((doc.request().velocities && doc.request().accelerations));

  for (const PlotQuantity q :
       {PlotQuantity::CouplerOmega, PlotQuantity::RockerOmega, PlotQuantity::CouplerAlpha, PlotQuantity::RockerAlpha})
    tick(panel, q, false);
  CHECK(selectionSpy.count() == 4);
  CHECK(doc.request().velocities == false);
  CHECK(doc.request().accelerations == false);
  CHECK(panel.chartView(QuantityKind::Omega)->isHidden());
  CHECK(panel.chartView(QuantityKind::Alpha)->isHidden());
  CHECK_FALSE(panel.chartView(QuantityKind::Angle)->isHidden());
  CHECK(plotted(panel, PlotQuantity::RockerOmega).isEmpty());

  tick(panel, PlotQuantity::RockerAlpha, true);
  CHECK(doc.request().accelerations == true);
  CHECK(doc.request().velocities == true);  // α needs ω
  CHECK_FALSE(panel.chartView(QuantityKind::Alpha)->isHidden());
  CHECK(panel.chartView(QuantityKind::Omega)->isHidden());
  CHECK(plotted(panel, PlotQuantity::RockerAlpha) ==
        expectedDegrees(doc.sweep(), doc.sweep().linkAlpha[kRocker], true));
  CHECK(plotted(panel, PlotQuantity::CouplerAlpha).isEmpty());

  tick(panel, PlotQuantity::RockerAlpha, false);
  tick(panel, PlotQuantity::CouplerOmega, true);
  CHECK((doc.request().velocities && !doc.request().accelerations));

  // A hidden angle curve is emptied and out of the legend; the chart stays for the others.
  tick(panel, PlotQuantity::CouplerAngle, false);
  const CurveItem* couplerLine = panel.chartView(QuantityKind::Angle)->curveItem(PlotQuantity::CouplerAngle);
  CHECK_FALSE(couplerLine->isVisible());
  CHECK(couplerLine->runs().isEmpty());
}

TEST_CASE("A new mechanism is swept once, for what the plots will show of it", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  for (const PlotQuantity q : {PlotQuantity::CouplerAlpha, PlotQuantity::RockerAlpha}) tick(panel, q, false);
  REQUIRE_FALSE(doc.request().accelerations);
  // Attaching a dyad brings new links, so the plots start from their defaults, α ticked: the
  // edit sweeps the display once for that (and the new linkage's grid once), never again
  // from the plots' own change handler.
  const auto attached =
      k::attachToDesign(doc.design(), k::suggestDyad(doc.mechanism(), doc.crankAngle(), k::DyadKind::Rrr));
  REQUIRE(attached.ok());
  const long before = doc.sweepsRun();
  REQUIRE_FALSE(doc.edit(*attached, "attach").has_value());
  CHECK(doc.sweepsRun() - before == 2);
  CHECK(doc.request().accelerations);
  CHECK_FALSE(panel.chartView(QuantityKind::Alpha)->isHidden());
  CHECK(plotted(panel, PlotQuantity::RockerAlpha) ==
        expectedDegrees(doc.sweep(), doc.sweep().linkAlpha[kRocker], true));
}

TEST_CASE("Radians convert angles, ω and α and the x axis", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  const QList<QPointF> omegaDeg = plotted(panel, PlotQuantity::RockerOmega);
  panel.setAngleUnit(AngleUnit::Radians);
  CHECK(panel.angleUnit() == AngleUnit::Radians);
  const k::SweepResult& s = doc.sweep();
  const QList<QPointF> omegaRad = plotted(panel, PlotQuantity::RockerOmega);
  const QList<QPointF> angleRad = plotted(panel, PlotQuantity::CouplerAngle);
  REQUIRE(omegaRad.size() == omegaDeg.size());
  for (std::size_t j : {std::size_t{10}, std::size_t{180}, std::size_t{600}}) {
    CAPTURE(j);
    const auto i = static_cast<qsizetype>(j);
    CHECK(omegaRad[i].y() == s.linkOmega[kRocker][j]);
    CHECK(omegaDeg[i].y() == Approx(omegaRad[i].y() * 180.0 / k::kPi));
    CHECK(angleRad[i].y() == s.linkAngle[kCoupler][j]);
    CHECK(angleRad[i].x() == s.inputAngle[j]);
  }
  const QuantityChartView* alpha = panel.chartView(QuantityKind::Alpha);
  CHECK(alpha->xAxis()->max() == Approx(2.0 * k::kPi));
  CHECK(alpha->xAxis()->titleText() == QStringLiteral("crank angle [rad]"));
  CHECK(alpha->yAxis()->titleText() == QStringLiteral("α [rad/s²]"));
  // The cursor moved with the unit: the crank is at 0 rad.
  doc.setCrankAngle(k::degToRad(90.0));
  CHECK(*alpha->cursorX() == Approx(k::kPi / 2.0));
}

TEST_CASE("A non-Grashof linkage plots nothing outside its assemblable range", "[plot_panel]") {
  MechanismDocument doc;
  doc.reset(nonGrashof());
  PlotPanel panel(&doc);
  const k::SweepResult& s = doc.sweep();
  qsizetype assembled = 0;
  for (std::size_t j = 0; j < s.size(); ++j) assembled += s.assembled(j) ? 1 : 0;
  REQUIRE(assembled > 0);
  REQUIRE(assembled < static_cast<qsizetype>(s.size()));  // there is a gap to get right

  for (const PlotQuantity q : fourBarQuantities()) tick(panel, q, true);  // the ratios too
  for (const PlotQuantity q : fourBarQuantities()) {
    CAPTURE(fourBarCurve(q).key);
    CHECK(panel.chartView(quantityKind(q))->curveItem(q)->runs().size() >= 2);  // the gap splits the line
    for (const QPointF& p : plotted(panel, q)) CHECK(doc.analysis().inputRange.contains(k::degToRad(p.x()), 1e-9));
  }
  CHECK(plotted(panel, PlotQuantity::RockerAngle).size() == assembled);
  CHECK(plotted(panel, PlotQuantity::RockerAngle) == expectedDegrees(s, s.linkAngle[kRocker], false));
  // Rates only where ok: none of the sweep's placeholder zeros.
  CHECK(plotted(panel, PlotQuantity::CouplerOmega) == expectedDegrees(s, s.linkOmega[kCoupler], true));
  CHECK(plotted(panel, PlotQuantity::RockerAlpha) == expectedDegrees(s, s.linkAlpha[kRocker], true));
  for (const PlotQuantity q :
       {PlotQuantity::CouplerOmega, PlotQuantity::RockerOmega, PlotQuantity::CouplerAlpha, PlotQuantity::RockerAlpha})
    for (const QPointF& p : plotted(panel, q)) CHECK(p.y() != 0.0);
}

TEST_CASE("a drag's sweep in a worker leaves the curves as they were until it lands, then plots it",
          "[plot_panel][worker]") {
  MechanismDocument doc;
  doc.setSweepThreading(DisplaySweeper::Threading::Worker);
  PlotPanel panel(&doc);
  const QList<QPointF> before = plotted(panel, PlotQuantity::RockerAngle);
  const k::Design d = linkwright::testing::withLengths(doc.design(), {60.0, 25.0, 65.0, 45.0});
  REQUIRE_FALSE(doc.edit(d, QStringLiteral("coupler"), MergeKey{ContinuousEdit::DragPoint, 1, 0}).has_value());
  REQUIRE(doc.sweepPending());
  CHECK(plotted(panel, PlotQuantity::RockerAngle) == before);
  doc.waitForSweep();
  CHECK(plotted(panel, PlotQuantity::RockerAngle) ==
        expectedDegrees(doc.sweep(), doc.sweep().linkAngle[kRocker], false));
  CHECK(plotted(panel, PlotQuantity::RockerAngle) != before);
  CHECK(plotted(panel, PlotQuantity::CouplerOmega) ==
        expectedDegrees(doc.sweep(), doc.sweep().linkOmega[kCoupler], true));
}

TEST_CASE("Moving the crank moves the cursor and leaves the data alone", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  std::vector<std::unique_ptr<QSignalSpy>> spies;
  QList<QList<QPointF>> before;
  for (QChartView* view : panel.chartViews())
    for (QAbstractSeries* series : view->chart()->series()) {
      auto* xy = qobject_cast<QXYSeries*>(series);
      if (xy == nullptr || xy->objectName() == QStringLiteral("cursor")) continue;
      spies.push_back(std::make_unique<QSignalSpy>(xy, &QXYSeries::pointsReplaced));
      before.append(xy->points());
    }
  REQUIRE(spies.size() >= 7);

  doc.setCrankAngle(k::degToRad(90.0));
  for (auto* view : panel.chartViews()) {
    const auto* chart = static_cast<QuantityChartView*>(view);
    REQUIRE(chart->cursorX().has_value());
    CHECK(*chart->cursorX() == Approx(90.0));
  }
  const auto* cursor = qobject_cast<QLineSeries*>([&] {
    for (QAbstractSeries* s : panel.chartViews()[0]->chart()->series())
      if (s->objectName() == QStringLiteral("cursor")) return s;
    return static_cast<QAbstractSeries*>(nullptr);
  }());
  REQUIRE(cursor != nullptr);
  CHECK(cursor->isVisible());
  REQUIRE(cursor->count() == 2);
  CHECK(cursor->at(0).x() == Approx(90.0));
  CHECK(cursor->at(1).x() == Approx(90.0));
  CHECK(cursor->at(0).y() == panel.chartView(QuantityKind::Angle)->yAxis()->min());
  CHECK(cursor->at(1).y() == panel.chartView(QuantityKind::Angle)->yAxis()->max());

  doc.setCrankAngle(k::degToRad(-30.0));  // wrapped into the 0–360° grid
  CHECK(*panel.chartView(QuantityKind::Omega)->cursorX() == Approx(330.0));

  for (const auto& spy : spies) CHECK(spy->count() == 0);
  qsizetype i = 0;
  for (QChartView* view : panel.chartViews())
    for (QAbstractSeries* series : view->chart()->series()) {
      auto* xy = qobject_cast<QXYSeries*>(series);
      if (xy == nullptr || xy->objectName() == QStringLiteral("cursor")) continue;
      CHECK(xy->points() == before[i++]);
    }
}

TEST_CASE("The angle chart marks the thesis crank-rocker's limits at 21.59° and 228.19°", "[plot_panel]") {
  MechanismDocument doc;  // the default design is the thesis crank-rocker, 60, 25, 70, 45 mm
  PlotPanel panel(&doc);
  const QList<double> lines = panel.limitMarkers()->lineXs();
  REQUIRE(lines.size() == 2);
  // The thesis prints two decimals.
  CHECK(lines[0] == Approx(21.59).margin(0.005));
  CHECK(lines[1] == Approx(228.19).margin(0.005));
  const QScatterSeries* points = panel.limitMarkers()->points();
  CHECK(points->isVisible());
  REQUIRE(points->count() == 2);
  CHECK(points->at(0).x() == lines[0]);
  CHECK(points->at(1).x() == lines[1]);
  CHECK(points->pointLabelsFormat() == QStringLiteral("limit"));
  CHECK(points->chart() == panel.chartView(QuantityKind::Angle)->chart());

  tick(panel, PlotQuantity::RockerAngle, false);  // no rocker curve to sit on
  CHECK_FALSE(points->isVisible());
  CHECK(panel.limitMarkers()->lineXs().size() == 2);

  MechanismDocument triple;
  triple.reset(nonGrashof());
  PlotPanel noLimits(&triple);
  CHECK(noLimits.limitMarkers()->lineXs().size() == static_cast<qsizetype>(triple.analysis().limits.positions.size()));
}

TEST_CASE("Hovering a curve reads out the nearest sample with its unit", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  REQUIRE(test::showSettled(panel, {700, 900}));
  QuantityChartView& view = *panel.chartView(QuantityKind::Omega);
  const CurveItem& omega = *view.curveItem(PlotQuantity::RockerOmega);
  // The mouse a pixel off the line near 90°, between samples: the read-out snaps to the sample
  // nearest the mouse's crank angle.
  const std::vector<double>& crankAngles = doc.sweep().inputAngle;
  const std::size_t at90 = static_cast<std::size_t>(
      std::min_element(crankAngles.begin(), crankAngles.end(),
                       [](double a, double b) { return std::abs(a - k::kPi / 2.0) < std::abs(b - k::kPi / 2.0); }) -
      crankAngles.begin());
  const QPoint pixel =
      test::pixelOf(view, omega, {k::radToDeg(crankAngles[at90]), k::radToDeg(doc.sweep().linkOmega[kRocker][at90])}) +
      QPoint(0, 1);
  const double crank = test::valueAt(view, omega, pixel).x();
  const QList<QPointF> samples = view.samples(PlotQuantity::RockerOmega);
  const QPointF sample = *std::min_element(samples.begin(), samples.end(), [crank](QPointF a, QPointF b) {
    return std::abs(a.x() - crank) < std::abs(b.x() - crank);
  });
  test::moveMouse(view, pixel);
  CHECK(panel.hoverReadout()->text() ==
        readoutText(fourBarCurve(PlotQuantity::RockerOmega), sample, AngleUnit::Degrees));
  CHECK(sample.x() == Approx(90.0).margin(1.0));
  CHECK(panel.hoverReadout()->text().contains(QStringLiteral(" deg/s at crank ")));
  // Off the curves (the chart's corner) it reads nothing.
  test::moveMouse(view, QPoint(2, 2));
  CHECK_FALSE(panel.hoverReadout()->text().contains(QStringLiteral("=")));
}

TEST_CASE("Legends name the shown curves and nothing else", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  tick(panel, PlotQuantity::CouplerOmega, false);
  panel.resize(900, 900);
  (void)panel.grab();  // lays the legends out
  const auto legendLabels = [](QChartView* view) {
    // The legend lays out new markers on a posted layout request, as the event loop would.
    QCoreApplication::sendPostedEvents();
    QStringList labels;
    for (QLegendMarker* marker : view->chart()->legend()->markers())
      if (marker->isVisible()) labels.append(marker->label());
    return labels;
  };
  CHECK(legendLabels(panel.chartViews()[0]) ==
        QStringList{fourBarCurve(PlotQuantity::CouplerAngle).name, fourBarCurve(PlotQuantity::RockerAngle).name,
                    fourBarCurve(PlotQuantity::TransmissionAngle).name, QStringLiteral("rocker limit")});
  CHECK(legendLabels(panel.chartViews()[1]) == QStringList{fourBarCurve(PlotQuantity::RockerOmega).name});
  CHECK(legendLabels(panel.chartViews()[2]) ==
        QStringList{fourBarCurve(PlotQuantity::CouplerAlpha).name, fourBarCurve(PlotQuantity::RockerAlpha).name});

  // A design with gaps draws the curves in more segments: still one legend entry per curve.
  const auto drawnSegments = [&panel] {
    return panel.chartView(QuantityKind::Alpha)->curveItem(PlotQuantity::RockerAlpha)->runs().size();
  };
  const auto segmentsBefore = drawnSegments();
  REQUIRE_FALSE(doc.edit(nonGrashof(), QStringLiteral("lengths")).has_value());
  REQUIRE(drawnSegments() > segmentsBefore);
  (void)panel.grab();
  CHECK(legendLabels(panel.chartViews()[2]) ==
        QStringList{fourBarCurve(PlotQuantity::CouplerAlpha).name, fourBarCurve(PlotQuantity::RockerAlpha).name});
  CHECK(legendLabels(panel.chartViews()[1]) == QStringList{fourBarCurve(PlotQuantity::RockerOmega).name});
}

TEST_CASE("a drag that leaves a value axis fits it again with room, and a single edit fits it tightly",
          "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  panel.resize(900, 1400);  // room for the ticks of a full-height chart
  (void)panel.grab();
  QuantityChartView* omega = panel.chartView(QuantityKind::Omega);
  const auto withCrank = [&doc](double factor) {
    k::Design d = doc.design();
    k::FourBarLengths lengths = doc.fourBar()->lengths;
    lengths.crank *= factor;
    d.mechanism = k::withFourBarLengths(d.mechanism, *doc.fourBar(), lengths);
    return d;
  };
  // What a panel of the same size, opened on the design, shows.
  const auto tightRange = [&doc] {
    PlotPanel fresh(&doc);
    fresh.resize(900, 1400);
    (void)fresh.grab();
    return fresh.chartView(QuantityKind::Omega)->valueRange();
  };
  // An edit after a quiet spell: the data have settled, the axis fits them as a new panel would.
  panel.settleValueRanges();
  AxisRange before = omega->valueRange();
  REQUIRE_FALSE(doc.edit(withCrank(0.5), "crank"));
  REQUIRE(omega->valueRange() != before);
  CHECK(omega->valueRange() == tightRange());
  // The next frame of a drag, within the settle time, leaves the axis: it is fitted with room.
  before = omega->valueRange();
  REQUIRE_FALSE(doc.edit(withCrank(0.5), "crank", MergeKey{ContinuousEdit::DragPoint, 1, 0}));
  REQUIRE(omega->valueRange() != before);
  const AxisRange roomy = omega->valueRange();
  CHECK(roomy != tightRange());
  CHECK(roomy.max - roomy.min > tightRange().max - tightRange().min);
  for (const QPointF& p : plotted(panel, PlotQuantity::RockerOmega)) {
    CHECK(p.y() >= roomy.min);
    CHECK(p.y() <= roomy.max);
  }
  panel.settleValueRanges();
  CHECK(omega->valueRange() == tightRange());
}

TEST_CASE("a drag into a rocking crank draws the gaps with the segments made ahead: no series is added",
          "[plot_panel]") {
  // A series added to a chart in the middle of a drag costs a frame (Qt Charts makes its item,
  // legend marker and axis links, then lays out and repaints the chart).
  MechanismDocument doc;
  PlotPanel panel(&doc);
  QChart* alpha = panel.chartView(QuantityKind::Alpha)->chart();
  const qsizetype seriesBefore = alpha->series().size();
  REQUIRE_FALSE(doc.edit(nonGrashof(), QStringLiteral("lengths"), MergeKey{ContinuousEdit::DragPoint, 1, 0}));
  REQUIRE(panel.chartView(QuantityKind::Alpha)->curveItem(PlotQuantity::RockerAlpha)->runs().size() >= 2);
  CHECK(alpha->series().size() == seriesBefore);
}

TEST_CASE("The plot areas line up so the cursor reads across the charts", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  panel.resize(900, 900);
  const auto check = [&panel] {
    (void)panel.grab();
    QList<QRectF> areas;
    for (QChartView* view : panel.chartViews())
      if (!view->isHidden()) areas.append(view->chart()->plotArea());
    REQUIRE(areas.size() >= 2);
    for (const QRectF& area : areas) {
      CHECK(area.left() == Approx(areas[0].left()).margin(1.0));
      CHECK(area.right() == Approx(areas[0].right()).margin(1.0));
      CHECK(area.width() > 0.5 * panel.width());  // the legend and labels leave room for the data
    }
  };
  check();
  tick(panel, PlotQuantity::TransmissionAngle, false);  // the widest legend entry goes
  check();
  panel.resize(700, 800);
  check();
  // Back to narrow after wide: the charts must not keep the wide layout's padding.
  panel.resize(900, 900);
  check();
  panel.resize(480, 900);
  check();
  CHECK(panel.width() == 480);
}

TEST_CASE("The checkbox row wraps in a narrow panel", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  CHECK(panel.minimumSizeHint().width() < 450);
  panel.resize(420, 900);
  (void)panel.grab();
  for (const PlotQuantity q : fourBarQuantities()) {
    const QCheckBox* box = panel.selector()->checkBox(q);
    CAPTURE(fourBarCurve(q).key);
    CHECK(box->mapTo(&panel, QPoint(box->width(), 0)).x() <= 420);
  }
}

TEST_CASE("The panel renders offscreen with curves in their colours", "[plot_panel][render]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  doc.setCrankAngle(k::degToRad(120.0));
  panel.resize(900, 900);
  const QImage image = panel.grab().toImage();
  CHECK(image.save(QStringLiteral("/tmp/linkwright_plots.png")));
  CHECK(image.width() == 900);  // the checkbox row does not force the panel wider
  // Curves drawn: pixels close to the coupler blue and the rocker green exist.
  const auto count = [&image](QColor colour) {
    qsizetype n = 0;
    for (int y = 0; y < image.height(); y += 1)
      for (int x = 0; x < image.width(); x += 1) {
        const QColor c = image.pixelColor(x, y);
        n += std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                         std::abs(c.blue() - colour.blue()) <
                     30
                 ? 1
                 : 0;
      }
    return n;
  };
  CHECK(count(fourBarCurve(PlotQuantity::CouplerAngle).color) > 500);
  CHECK(count(fourBarCurve(PlotQuantity::RockerAngle).color) > 500);

  MechanismDocument triple;
  triple.reset(nonGrashof());
  PlotPanel gaps(&triple);
  gaps.resize(900, 900);
  CHECK(gaps.grab().save(QStringLiteral("/tmp/linkwright_plots_non_grashof.png")));

  panel.setAngleUnit(AngleUnit::Radians);
  panel.resize(480, 900);
  CHECK(panel.grab().save(QStringLiteral("/tmp/linkwright_plots_radians_narrow.png")));
}

TEST_CASE("during a drag the value axes hold the data, and fit them once they settle", "[plot_panel]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  QuantityChartView* omega = panel.chartView(QuantityKind::Omega);
  // Frames of a drag shortening the crank: whether an axis stays (keepsRange, tested in
  // axis_range_test.cpp) or is fitted again, every plotted value lies on it.
  for (int frame = 1; frame <= 8; ++frame) {
    k::Design shorter = doc.design();
    k::FourBarLengths lengths = doc.fourBar()->lengths;
    lengths.crank -= 0.25;
    shorter.mechanism = k::withFourBarLengths(shorter.mechanism, *doc.fourBar(), lengths);
    REQUIRE_FALSE(doc.edit(shorter, "crank", MergeKey{ContinuousEdit::DragPoint, 1, 0}));
    for (const QPointF& p : plotted(panel, PlotQuantity::RockerOmega)) {
      CHECK(p.y() >= omega->yAxis()->min());
      CHECK(p.y() <= omega->yAxis()->max());
    }
  }
  // Settled: the range a panel opened on this design shows.
  panel.settleValueRanges();
  PlotPanel fresh(&doc);
  CHECK(omega->valueRange() == fresh.chartView(QuantityKind::Omega)->valueRange());
  CHECK(omega->yAxis()->min() == omega->valueRange().min);
  CHECK(omega->yAxis()->max() == omega->valueRange().max);
}
