// The curves hold only the vertices a screen can show (ui/screen_simplify.h): every
// sample stays within the tolerance of the line drawn, peaks are kept, and the hover read-out
// still gives the exact sample, drawn or not.
#include "ui/screen_simplify.h"

#include "four_bar_curves.h"
#include "mouse_on_curve.h"

#include "ui/plots/hover_readout.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/segmented_line.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include <QChart>
#include <QTest>
#include <QValueAxis>

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::ui;
using linkwright::ui::test::fourBarCurve;
namespace k = linkwright::kinematics;

namespace {

// Pixels from p to the polyline `line` at `scale`.
double pixelDistance(QPointF p, const QList<QPointF>& line, const ScreenScale& scale) {
  double best = std::numeric_limits<double>::infinity();
  for (qsizetype i = 0; i + 1 < line.size(); ++i) {
    const double ax = line[i].x() * scale.xPixelsPerUnit, ay = line[i].y() * scale.yPixelsPerUnit;
    const double bx = line[i + 1].x() * scale.xPixelsPerUnit - ax, by = line[i + 1].y() * scale.yPixelsPerUnit - ay;
    const double px = p.x() * scale.xPixelsPerUnit - ax, py = p.y() * scale.yPixelsPerUnit - ay;
    const double t = std::clamp((px * bx + py * by) / (bx * bx + by * by), 0.0, 1.0);
    best = std::min(best, std::hypot(px - t * bx, py - t * by));
  }
  return line.size() == 1
             ? std::hypot((p.x() - line[0].x()) * scale.xPixelsPerUnit, (p.y() - line[0].y()) * scale.yPixelsPerUnit)
             : best;
}

// Whether `kept` is `all` with some points left out, in order.
bool isOrderedSubset(const QList<QPointF>& kept, const QList<QPointF>& all) {
  qsizetype j = 0;
  for (const QPointF& p : kept) {
    while (j < all.size() && all[j] != p) ++j;
    if (j == all.size()) return false;
    ++j;
  }
  return true;
}

double worstDistance(const QList<QPointF>& all, const QList<QPointF>& kept, const ScreenScale& scale) {
  double worst = 0.0;
  for (const QPointF& p : all) worst = std::max(worst, pixelDistance(p, kept, scale));
  return worst;
}

}  // namespace

TEST_CASE("a smooth curve keeps a few vertices, each sample within the tolerance of them", "[plots][simplify]") {
  QList<QPointF> sine;
  for (int i = 0; i <= 720; ++i) sine.append({0.5 * i, 100.0 * std::sin(k::degToRad(0.5 * i))});
  const ScreenScale scale{500.0 / 360.0, 200.0 / 220.0};  // 500 × 200 px for 0–360° × ±110
  QList<QPointF> kept;
  SimplifyScratch scratch;
  simplifyForScreen(sine, scale, 0.2, kept, scratch);
  CHECK(kept.front() == sine.front());
  CHECK(kept.back() == sine.back());
  CHECK(isOrderedSubset(kept, sine));
  CHECK(worstDistance(sine, kept, scale) <= 0.2);
  CHECK(kept.size() < sine.size() / 10);
  // The peak's own sample is among them, to a fraction of a pixel.
  CHECK(std::any_of(kept.begin(), kept.end(), [](QPointF p) { return std::abs(p.x() - 90.0) < 2.0; }));
}

TEST_CASE("a one-sample spike and a kink are kept exactly", "[plots][simplify]") {
  QList<QPointF> line;
  for (int i = 0; i <= 100; ++i) line.append({double(i), i == 37 ? 50.0 : (i < 60 ? 0.0 : i - 60.0)});
  QList<QPointF> kept;
  SimplifyScratch scratch;
  simplifyForScreen(line, {4.0, 4.0}, 0.2, kept, scratch);
  CHECK(kept == QList<QPointF>{{0, 0}, {36, 0}, {37, 50}, {38, 0}, {60, 0}, {100, 40}});
}

TEST_CASE("without a usable scale or tolerance every point is kept", "[plots][simplify]") {
  const QList<QPointF> line{{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  QList<QPointF> kept;
  SimplifyScratch scratch;
  for (const ScreenScale scale :
       {ScreenScale{0.0, 1.0}, ScreenScale{1.0, -1.0}, ScreenScale{std::nan(""), 1.0}, ScreenScale{1.0, INFINITY}}) {
    simplifyForScreen(line, scale, 0.2, kept, scratch);
    CHECK(kept == line);
  }
  simplifyForScreen(line, {1.0, 1.0}, 0.0, kept, scratch);
  CHECK(kept == line);
  simplifyForScreen(line, {1.0, 1.0}, 0.2, kept, scratch);
  CHECK(kept == QList<QPointF>{{0, 0}, {3, 0}});
}

TEST_CASE("a shown chart draws fewer vertices than samples, every sample within 0.2 px, hover exact",
          "[plots][simplify]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  REQUIRE(test::showSettled(panel, {600, 700}));
  QuantityChartView* view = panel.chartView(QuantityKind::Omega);
  const QRectF area = view->chart()->plotArea();
  REQUIRE(area.width() > 100.0);
  const ScreenScale scale{area.width() / (view->xAxis()->max() - view->xAxis()->min()),
                          area.height() / (view->yAxis()->max() - view->yAxis()->min())};
  for (const PlotQuantity q : {PlotQuantity::CouplerOmega, PlotQuantity::RockerOmega}) {
    const QList<QPointF> samples = view->samples(q);
    QList<QPointF> drawn;
    for (const QList<QPointF>& run : view->curveItem(q)->runs()) drawn += run;
    REQUIRE(samples.size() == static_cast<qsizetype>(doc.sweep().size()));  // a crank-rocker: no gaps
    CHECK(drawn.size() < samples.size() / 3);
    CHECK(isOrderedSubset(drawn, samples));
    CHECK(worstDistance(samples, drawn, scale) <= SegmentedLine::kCurveTolerancePx * 1.05);
  }
  // The sample at 90° is not a drawn vertex, yet hovering there reads it out exactly.
  // (The mouse moves in whole pixels: the sample is the one nearest the pixel's crank angle.)
  const CurveItem& omega = *view->curveItem(PlotQuantity::RockerOmega);
  const std::size_t at90 =
      static_cast<std::size_t>(std::lround(90.0 / 360.0 * static_cast<double>(doc.sweep().size() - 1)));
  const QPoint pixel =
      test::pixelOf(*view, omega, {90.0, k::radToDeg(doc.sweep().linkOmega[k::fourbar::kRocker.index][at90])});
  const double crank = test::valueAt(*view, omega, pixel).x();
  const QList<QPointF> samples = view->samples(PlotQuantity::RockerOmega);
  const QPointF sample = *std::min_element(samples.begin(), samples.end(), [crank](QPointF a, QPointF b) {
    return std::abs(a.x() - crank) < std::abs(b.x() - crank);
  });
  REQUIRE_FALSE(omega.runs().front().contains(sample));
  test::moveMouse(*view, pixel);
  CHECK(panel.hoverReadout()->text() ==
        readoutText(fourBarCurve(PlotQuantity::RockerOmega), sample, AngleUnit::Degrees));
}
