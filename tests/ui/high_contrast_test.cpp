// View ▸ High contrast (ui/colors.h) and the big read-out in the window: every high-contrast
// colour a link, slider or transmission angle is drawn in reads on white at WCAG's 4.5:1;
// switching recolours the canvas's links, the plots' curves and the charts' frame, and back;
// presentation mode brings the read-out and takes it away again.

#include "ui/canvas/link_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/classroom/big_readout.h"
#include "ui/classroom/polygon_view.h"
#include "ui/colors.h"
#include "ui/main_window.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include "kinematics/model/fourbar.h"

#include "tests/support/catch.h"

#include <QChart>
#include <QValueAxis>

#include <cmath>

using namespace linkwright::ui;
namespace fourbar = linkwright::kinematics::fourbar;

namespace {

// WCAG 2's relative luminance of an sRGB colour and its contrast ratio against white.
double relativeLuminance(const QColor& c) {
  const auto channel = [](int v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * channel(c.red()) + 0.7152 * channel(c.green()) + 0.0722 * channel(c.blue());
}

double contrastOnWhite(const QColor& c) { return (1.0 + 0.05) / (relativeLuminance(c) + 0.05); }

// The theme is process-wide: a test that changes it puts it back, pass or fail.
struct NormalThemeAfter {
  ~NormalThemeAfter() { setTheme(Theme::Normal); }
};

const LinkageScene& sceneOf(const MainWindow& window) {
  return *static_cast<const LinkageScene*>(window.canvas()->linkageScene());
}

QColor curveColour(const MainWindow& window, PlotQuantity quantity) {
  const CurveItem* curve = window.plots()->chartView(QuantityKind::Angle)->curveItem(quantity);
  REQUIRE(curve != nullptr);
  return curve->pen().color();
}

}  // namespace

TEST_CASE("every high-contrast link, slider, transmission and classroom colour reads on white at 4.5:1",
          "[ui][colors]") {
  const Palette& hc = paletteOf(Theme::HighContrast);
  for (const QColor& c : hc.links) {
    CAPTURE(c.name());
    CHECK(contrastOnWhite(c) >= 4.5);
  }
  for (const QColor& c : hc.sliders) CHECK(contrastOnWhite(c) >= 4.5);
  for (const QColor& c : hc.transmissions) CHECK(contrastOnWhite(c) >= 4.5);
  // The classroom's drawings too: the polygons' arrows and the instant centres.
  for (const QColor& c : hc.polygonTerms) CHECK(contrastOnWhite(c) >= 4.5);
  for (const QColor& c : {hc.centre, hc.kennedyLine, hc.movingCentrode}) CHECK(contrastOnWhite(c) >= 4.5);
  CHECK(contrastOnWhite(paletteOf(Theme::Normal).movingCentrode) < 4.5);  // why they change
  NormalThemeAfter restore;
  setTheme(Theme::HighContrast);
  CHECK(polygonTermColor(linkwright::kinematics::VectorTerm::Coriolis) == hc.polygonTerms[5]);
  setTheme(Theme::Normal);
  CHECK(polygonTermColor(linkwright::kinematics::VectorTerm::Coriolis) == paletteOf(Theme::Normal).polygonTerms[5]);
  CHECK(contrastOnWhite(hc.label) == Approx(21.0));  // black on white
  // The formula itself: the normal crank orange is the lighter one, under the threshold.
  CHECK(contrastOnWhite(paletteOf(Theme::Normal).links[0]) < 4.5);
}

TEST_CASE("high contrast recolours the canvas's links and the plots' curves, and back", "[ui][colors]") {
  NormalThemeAfter restore;
  MainWindow window;
  const Palette& normal = paletteOf(Theme::Normal);
  const Palette& hc = paletteOf(Theme::HighContrast);
  REQUIRE_FALSE(window.highContrast());
  CHECK(sceneOf(window).linkItem(fourbar::kRocker)->pen().color() == normal.links[fourbar::kRocker.index]);
  CHECK(curveColour(window, PlotQuantity::RockerAngle) == normal.links[fourbar::kRocker.index]);
  QChart* chart = window.plots()->chartView(QuantityKind::Angle)->chart();
  const QBrush ownLabels = chart->axes(Qt::Vertical).front()->labelsBrush();

  window.setHighContrast(true);
  CHECK(window.highContrast());
  // The items are made anew in the new colours: look them up again.
  CHECK(sceneOf(window).linkItem(fourbar::kCrank)->pen().color() == hc.links[fourbar::kCrank.index]);
  CHECK(sceneOf(window).linkItem(fourbar::kRocker)->pen().color() == hc.links[fourbar::kRocker.index]);
  CHECK(curveColour(window, PlotQuantity::RockerAngle) == hc.links[fourbar::kRocker.index]);
  CHECK(curveColour(window, PlotQuantity::CouplerAngle) == hc.links[fourbar::kCoupler.index]);
  CHECK(chart->backgroundBrush().color() == QColor(Qt::white));
  CHECK(chart->titleBrush().color() == QColor(Qt::black));
  CHECK(chart->axes(Qt::Vertical).front()->labelsBrush().color() == QColor(Qt::black));
  // The curve is drawn (setData ran on the new series), not only made.
  CHECK_FALSE(window.plots()->chartView(QuantityKind::Angle)->samples(PlotQuantity::RockerAngle).isEmpty());

  window.setHighContrast(false);
  CHECK(sceneOf(window).linkItem(fourbar::kRocker)->pen().color() == normal.links[fourbar::kRocker.index]);
  CHECK(curveColour(window, PlotQuantity::RockerAngle) == normal.links[fourbar::kRocker.index]);
  CHECK(chart->axes(Qt::Vertical).front()->labelsBrush() == ownLabels);
}

TEST_CASE("presentation mode brings the big read-out and leaving takes it away", "[ui][window][readout]") {
  MainWindow window;
  CHECK(window.bigReadout()->isHidden());
  window.setPresentationMode(true);
  CHECK_FALSE(window.bigReadout()->isHidden());
  // Larger than the window's text, itself enlarged for the class (and shrunk only to fit).
  CHECK(window.bigReadout()->font().pointSizeF() > window.font().pointSizeF());
  CHECK_FALSE(window.highContrast());  // presentation does not impose it
  window.setPresentationMode(false);
  CHECK(window.bigReadout()->isHidden());
  window.setShowBigReadout(true);
  CHECK_FALSE(window.bigReadout()->isHidden());
}
