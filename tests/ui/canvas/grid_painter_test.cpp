// The grid's spacing follows the 1-2-5 sequence and keeps lines 40 to 100 pixels apart.

#include "canvas_test_support.h"

#include "ui/canvas/grid_painter.h"

#include "tests/support/catch.h"

#include <QFontMetricsF>

#include <cmath>
#include <tuple>

using linkwright::ui::formatGridValue;
using linkwright::ui::gridSpacing;
using linkwright::ui::test::ShownView;

namespace {

// True if `spacing` is 1, 2 or 5 times a power of ten.
bool isOneTwoFive(double spacing) {
  const double decade = std::pow(10.0, std::floor(std::log10(spacing) + 1e-9));
  const double mantissa = spacing / decade;
  return std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 || std::abs(mantissa - 5.0) < 1e-9;
}

void requireGridRule(double spacing, double pixelsPerUnit) {
  CAPTURE(spacing, pixelsPerUnit);
  CHECK(isOneTwoFive(spacing));
  CHECK(spacing * pixelsPerUnit >= 40.0 - 1e-9);
  CHECK(spacing * pixelsPerUnit <= 100.0);
}

}  // namespace

TEST_CASE("grid spacing from the 1-2-5 sequence", "[canvas][grid]") {
  double pixelsPerUnit = 0.0, expected = 0.0;
  std::tie(pixelsPerUnit, expected) = GENERATE(table<double, double>({
      {1.0, 50.0},     // 40 units needed: 50
      {4.0, 10.0},     // exactly 10
      {3.0, 20.0},     // 13.3 needed
      {0.4, 100.0},    // exactly 100
      {40.0, 1.0},     // exactly 1
      {100.0, 0.5},    // 0.4 needed
      {7000.0, 0.01},  // 0.0057 needed
  }));
  CAPTURE(pixelsPerUnit);
  CHECK(gridSpacing(pixelsPerUnit) == Approx(expected));
  requireGridRule(gridSpacing(pixelsPerUnit), pixelsPerUnit);
}

TEST_CASE("grid spacing keeps the rule over nine decades of zoom", "[canvas][grid]") {
  for (double ppu = 1e-4; ppu < 1e5; ppu *= 1.037) requireGridRule(gridSpacing(ppu), ppu);
  CHECK(gridSpacing(0.0) == 1.0);
  CHECK(gridSpacing(std::nan("")) == 1.0);
}

TEST_CASE("grid values are written with the decimals the spacing needs", "[canvas][grid]") {
  CHECK(formatGridValue(120.0, 20.0) == "120");
  CHECK(formatGridValue(0.15, 0.05) == "0.15");
  CHECK(formatGridValue(-1e-17, 0.5) == "0.0");
  CHECK(formatGridValue(-2.0, 1.0) == "-2");
}

TEST_CASE("the view's grid follows the rule at two zoom levels", "[canvas][grid]") {
  ShownView v;
  const double fitted = v.view.gridSpacing();
  requireGridRule(fitted, v.view.pixelsPerUnit());
  v.wheel(QPoint(400, 300), 10);  // 1.2^10 ≈ 6.2 times closer
  const double zoomed = v.view.gridSpacing();
  requireGridRule(zoomed, v.view.pixelsPerUnit());
  CHECK(zoomed < fitted);
}

// Presentation mode on a projector's 1024×768 screen: 8 pt × 2 numbers on lines 40–100 px apart
// ran together ("-10-5 0 5 10", "30grid 5 mm"). No two numbers or the caption overlap, the
// bottom numbers keep a digit apart, at text scales 1 and 2 over a range of zooms.
TEST_CASE("the grid's numbers never run together, whatever the text scale", "[canvas][grid]") {
  using linkwright::ui::gridLabelFont;
  using linkwright::ui::gridLabels;
  const QRectF visible(-12.0, -14.0, 48.0, 40.0);  // mm: the funsho four-bar's drawing
  for (const double textScale : {1.0, 2.0})
    for (const double pixelsPerUnit : {8.0, 9.0, 12.5, 20.0, 33.0}) {
      CAPTURE(textScale, pixelsPerUnit);
      const QTransform toDevice = QTransform::fromScale(pixelsPerUnit, -pixelsPerUnit).translate(12.0, -26.0);
      const double spacing = gridSpacing(pixelsPerUnit);
      const QFont font = gridLabelFont(QFont(), textScale);
      const auto labels = gridLabels(toDevice, visible, spacing, QStringLiteral("mm"), font, textScale);
      const double digit = QFontMetricsF(font).horizontalAdvance(QStringLiteral("0"));
      std::size_t bottom = 0;
      for (std::size_t i = 0; i < labels.size(); ++i) {
        for (std::size_t j = i + 1; j < labels.size(); ++j) {
          CAPTURE(labels[i].text, labels[j].text);
          CHECK_FALSE(labels[i].box.intersects(labels[j].box));
          if (labels[i].at.y() == labels[j].at.y())  // along the bottom
            CHECK(std::abs(labels[i].box.center().x() - labels[j].box.center().x()) >=
                  0.5 * (labels[i].box.width() + labels[j].box.width()) + digit - 1e-9);
        }
        bottom += labels[i].at.y() == labels.back().at.y() ? 1 : 0;
      }
      CHECK(bottom >= 3);  // the caption and at least two numbers
    }
}
