// Tests ui/plots/curve_item.h: a curve drawn by our own item lands where Qt Charts maps its
// values, in its legend entry's pen, run by run, follows the axes, and tells which run the
// mouse is on.
#include "ui/plots/curve_item.h"

#include "mouse_on_curve.h"

#include "ui/plots/crank_angle_chart.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QGraphicsLayout>
#include <QImage>
#include <QLineSeries>
#include <QSignalSpy>
#include <QTest>
#include <QValueAxis>

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::ui;

namespace {

const QColor kLineColour(0, 90, 200);

// A crank-angle chart of 0…360 against -2…2, with one curve of two runs: a rising line
// 0…100 and a falling one 200…300 (no line joins 100 to 200).
struct ChartWithCurve {
  QChartView view;
  QValueAxis* x = new QValueAxis;
  QValueAxis* y = new QValueAxis;
  QLineSeries* legendEntry = new QLineSeries;
  CurveItem* curve = nullptr;

  ChartWithCurve() {
    view.setChart(makeCrankAngleChart(QStringLiteral("angles"), x, y));
    x->setRange(0.0, 360.0);
    y->setRange(-2.0, 2.0);
    legendEntry->setPen(QPen(kLineColour, 2.0));
    view.chart()->addSeries(legendEntry);
    legendEntry->attachAxis(x);
    legendEntry->attachAxis(y);
    curve = new CurveItem(view.chart(), x, y, legendEntry);
    curve->setRuns({{{0.0, -1.0}, {100.0, 1.0}}, {{200.0, 1.0}, {300.0, -1.0}}});
    view.resize(520, 320);
    view.show();
    REQUIRE(QTest::qWaitForWindowExposed(&view));
    view.chart()->layout()->activate();
    QApplication::processEvents();
  }

  // The colour painted at `value` (plot units).
  QColor colourAt(QPointF value) {
    const QImage image = view.grab().toImage();
    const QPoint p = test::pixelOf(view, *curve, value) * image.devicePixelRatio();
    return image.pixelColor(p);
  }
};

// Whether `curve`'s bounding rect holds every vertex it draws (else a repaint of the rect
// would leave trails of the old line), and stays within the plot area.
bool boundsHoldLine(const CurveItem& curve, const QRectF& area) {
  const QRectF bounds = curve.boundingRect();
  for (const QList<QPointF>& run : curve.runs())
    for (const QPointF& p : run) {
      const QPointF at = curve.toChart(p);
      if (area.contains(at) && !bounds.contains(at)) return false;
    }
  return area.adjusted(-1.0, -1.0, 1.0, 1.0).contains(bounds);
}

bool isLine(const QColor& c) {
  // Antialiased: within a few steps of the pen's colour at the line's centre.
  return std::abs(c.red() - kLineColour.red()) < 40 && std::abs(c.green() - kLineColour.green()) < 40 &&
         std::abs(c.blue() - kLineColour.blue()) < 40;
}

}  // namespace

TEST_CASE("A curve item maps its values as Qt Charts does, and back", "[plots][curve]") {
  ChartWithCurve c;
  QChart* chart = c.view.chart();
  for (const QPointF value : {QPointF(0.0, -2.0), QPointF(360.0, 2.0), QPointF(90.0, 0.5), QPointF(271.3, -1.7)}) {
    CAPTURE(value);
    const QPointF ours = c.curve->toChart(value);
    const QPointF qts = chart->mapToPosition(value, c.legendEntry);
    CHECK(ours.x() == Approx(qts.x()).margin(1e-9));
    CHECK(ours.y() == Approx(qts.y()).margin(1e-9));
    const QPointF back = c.curve->toValue(ours);
    CHECK(back.x() == Approx(value.x()).margin(1e-9));
    CHECK(back.y() == Approx(value.y()).margin(1e-9));
  }
  // A reversed axis is drawn from its other end, as Qt Charts draws it.
  c.x->setReverse(true);
  c.view.chart()->layout()->activate();
  const QPointF reversed = chart->mapToPosition({90.0, 0.5}, c.legendEntry);
  CHECK(c.curve->toChart({90.0, 0.5}).x() == Approx(reversed.x()).margin(1e-9));
}

TEST_CASE("A curve item draws each run in its legend entry's pen, and nothing between runs", "[plots][curve]") {
  ChartWithCurve c;
  CHECK(c.curve->pen() == c.legendEntry->pen());
  CHECK(boundsHoldLine(*c.curve, c.view.chart()->plotArea()));
  CHECK(isLine(c.colourAt({50.0, 0.0})));         // the middle of the first run
  CHECK(isLine(c.colourAt({250.0, 0.0})));        // and of the second
  CHECK_FALSE(isLine(c.colourAt({150.0, 1.0})));  // the gap between them stays empty
  CHECK_FALSE(isLine(c.colourAt({50.0, 1.0})));

  // A new pen on the legend entry (a theme, presentation mode) is the line's pen.
  const QColor red(220, 0, 0);
  c.legendEntry->setPen(QPen(red, 2.0));
  QApplication::processEvents();
  CHECK(c.curve->pen().color() == red);
  CHECK(c.colourAt({50.0, 0.0}) == red);
}

TEST_CASE("A curve item follows a new axis range without new runs", "[plots][curve]") {
  ChartWithCurve c;
  QSignalSpy replaced(c.curve, &CurveItem::runsReplaced);
  c.y->setRange(-4.0, 4.0);
  QApplication::processEvents();
  CHECK(isLine(c.colourAt({50.0, 0.0})));
  CHECK(isLine(c.colourAt({75.0, 0.5})));
  const QPointF moved = c.curve->toChart({75.0, 0.5});
  CHECK(moved.y() == Approx(c.view.chart()->mapToPosition({75.0, 0.5}, c.legendEntry).y()).margin(1e-9));
  CHECK(replaced.isEmpty());
  CHECK(boundsHoldLine(*c.curve, c.view.chart()->plotArea()));
}

TEST_CASE("A curve item clips a line that runs far off its axes", "[plots][curve]") {
  ChartWithCurve c;
  // A spike next to a toggle position: a value a trillion times the axis.
  c.curve->setRuns({{{0.0, 0.0}, {40.0, 0.0}, {50.0, 1e12}, {60.0, 0.0}, {160.0, 1.0}}});
  QApplication::processEvents();
  CHECK(isLine(c.colourAt({110.0, 0.5})));  // the rest of the line is drawn
  CHECK(boundsHoldLine(*c.curve, c.view.chart()->plotArea()));
  // The spike rises straight up from 40: drawn up to the top of the plot area, not past it.
  const QRectF area = c.view.chart()->plotArea();
  const double spikeX = c.curve->toValue({c.curve->toChart({40.0, 0.0}).x(), 0.0}).x();
  CHECK(isLine(c.colourAt({spikeX, c.curve->toValue({0.0, area.top() + 6.0}).y()})));
  CHECK_FALSE(isLine(c.colourAt({spikeX, c.curve->toValue({0.0, area.top() - 6.0}).y()})));
  // A run of one point, and no runs at all, draw nothing and do not fail.
  c.curve->setRuns({{{50.0, 0.0}}});
  (void)c.view.grab();
  c.curve->setRuns({});
  CHECK_FALSE(isLine(c.colourAt({50.0, 0.0})));
}

TEST_CASE("Hovering a curve item says which run the mouse is on, and where", "[plots][curve]") {
  ChartWithCurve c;
  QSignalSpy hovered(c.curve, &CurveItem::hovered);
  const QPoint onSecond = test::pixelOf(c.view, *c.curve, {250.0, 0.0});
  test::moveMouse(c.view, onSecond + QPoint(0, 2));  // two pixels off the line still points at it
  REQUIRE(hovered.count() == 1);
  CHECK(hovered[0][0].value<qsizetype>() == 1);
  CHECK(hovered[0][1].toPointF().x() == Approx(250.0).margin(1.0));
  CHECK(hovered[0][2].toBool());
  // Along the line, each move says where; off it, the mouse has left the run.
  test::moveMouse(c.view, test::pixelOf(c.view, *c.curve, {280.0, -0.6}));
  REQUIRE(hovered.count() == 2);
  CHECK(hovered[1][1].toPointF().x() == Approx(280.0).margin(1.0));
  test::moveMouse(c.view, test::pixelOf(c.view, *c.curve, {150.0, 0.0}));
  REQUIRE(hovered.count() == 3);
  CHECK(hovered[2][0].value<qsizetype>() == 1);
  CHECK_FALSE(hovered[2][2].toBool());
  test::moveMouse(c.view, test::pixelOf(c.view, *c.curve, {50.0, 0.0}));
  REQUIRE(hovered.count() == 4);
  CHECK(hovered[3][0].value<qsizetype>() == 0);
  CHECK(hovered[3][2].toBool());
}
