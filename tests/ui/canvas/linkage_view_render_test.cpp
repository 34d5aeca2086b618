// Rendering offscreen: the view (with its grid) and the export of the scene give real
// pictures. The PNGs in /tmp are for a person to look at.

#include "canvas_test_support.h"

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/label_item.h"

#include <QImage>
#include <QPainter>

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace k = linkwright::kinematics;
namespace fourbar = linkwright::kinematics::fourbar;
namespace canvas = linkwright::ui::canvas;
namespace ui = linkwright::ui;
using linkwright::ui::test::nonGrashofDesign;
using linkwright::ui::test::ShownView;

namespace {

// Pixels close to `colour` (antialiasing blends edges, so a small tolerance).
int countNear(const QImage& image, const QColor& colour) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) + std::abs(c.blue() - colour.blue()) <
          24)
        ++count;
    }
  return count;
}

// What a translucent colour looks like painted over white.
QColor overWhite(const QColor& colour) {
  const auto blend = [&](int channel) {
    return static_cast<int>(std::lround(255.0 - (255.0 - channel) * colour.alphaF()));
  };
  return QColor(blend(colour.red()), blend(colour.green()), blend(colour.blue()));
}

// The most pixels near `colour` in one row or one column: a grid line fills a whole one.
int longestLine(const QImage& image, const QColor& colour) {
  const auto near = [&](int x, int y) {
    const QColor c = image.pixelColor(x, y);
    return std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
               std::abs(c.blue() - colour.blue()) <
           8;
  };
  int most = 0;
  for (int y = 0; y < image.height(); ++y) {
    int n = 0;
    for (int x = 0; x < image.width(); ++x) n += near(x, y) ? 1 : 0;
    most = std::max(most, n);
  }
  for (int x = 0; x < image.width(); ++x) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y) n += near(x, y) ? 1 : 0;
    most = std::max(most, n);
  }
  return most;
}

// What the user sees: the widget's own paint path (QGraphicsView::render takes another path,
// which skips labels offset from their anchor when zoomed far in).
QImage grabView(ShownView& v) { return v.view.grab().toImage().convertToFormat(QImage::Format_ARGB32); }

}  // namespace

TEST_CASE("the view renders the linkage with its grid", "[canvas][render]") {
  ShownView v;
  v.view.setShowVelocityArrows(true);
  const QImage image = grabView(v);
  REQUIRE_FALSE(image.isNull());
  CHECK(image.save("/tmp/linkwright_canvas_default.png"));
  // Every link is visible: a 6 px bar gives hundreds of pixels of its colour.
  CHECK(countNear(image, ui::linkColor(0)) > 100);
  CHECK(countNear(image, ui::linkColor(1)) > 100);
  CHECK(countNear(image, ui::linkColor(2)) > 100);
  CHECK(longestLine(image, ui::colors().grid) > image.width() / 2);
  // The crank is drawn where the view maps it: its midpoint has the crank's colour.
  const QPoint middle = v.pixelOf((v.point(fourbar::kO2) + v.point(fourbar::kB)) / 2.0);
  const QColor atMiddle = image.pixelColor(middle);
  CHECK(std::abs(atMiddle.red() - ui::linkColor(0).red()) < 24);
  CHECK(std::abs(atMiddle.blue() - ui::linkColor(0).blue()) < 24);
}

TEST_CASE("a non-Grashof linkage shows its unreachable crank angles", "[canvas][render]") {
  k::Design design =
      k::fourBarDesign({40.0, 30.0, 20.0, 25.0}, k::Branch::Open, "mm", k::CouplerPointSpec{10.0, 8.0}).value();
  ShownView v(design);
  const QImage image = grabView(v);
  CHECK(image.save("/tmp/linkwright_canvas_nongrashof.png"));
  CHECK(countNear(image, overWhite(ui::colors().feasible)) > 500);
  CHECK(countNear(image, ui::colors().couplerPoint) > 50);
}

TEST_CASE("presentation mode renders bigger", "[canvas][render]") {
  ShownView v;
  const int normal = countNear(grabView(v), ui::linkColor(1));
  v.view.setPresentationScale(2.0);
  const QImage big = grabView(v);
  CHECK(big.save("/tmp/linkwright_canvas_presentation.png"));
  CHECK(countNear(big, ui::linkColor(1)) > 3 * normal / 2);
}

TEST_CASE("the export draws the scene upright, without the grid", "[canvas][render]") {
  ShownView v;
  QImage image(900, 700, QImage::Format_ARGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  v.view.renderLinkage(&painter, QRectF(0, 0, 900, 700));
  painter.end();
  CHECK(image.save("/tmp/linkwright_canvas_export.png"));
  CHECK(countNear(image, ui::linkColor(1)) > 100);
  CHECK(longestLine(image, ui::colors().grid) < image.width() / 4);
  // y up: C (above the frame line) is in the upper part of the picture, the frame line lower.
  int couplerRows = 0, couplerRowSum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.pixelColor(x, y) == ui::linkColor(1)) {
        ++couplerRows;
        couplerRowSum += y;
      }
  REQUIRE(couplerRows > 0);
  CHECK(couplerRowSum / couplerRows < image.height() / 2);
}

TEST_CASE("a refused drag shows its reason next to the cursor", "[canvas][render]") {
  ShownView v;
  const QPointF b = v.point(fourbar::kB);
  QTest::mousePress(v.viewport(), Qt::LeftButton, Qt::NoModifier, v.pixelOf(b));
  QTest::mouseMove(v.viewport(), v.pixelOf(b + QPointF(25.0, -5.0)));
  // 200 mm out: past coupler + rocker at any angle, and past the view's right edge.
  const QPoint far = v.pixelOf(b + QPointF(200.0, -5.0));
  REQUIRE(far.x() > v.viewport()->width());
  QTest::mouseMove(v.viewport(), far);
  const QImage image = grabView(v);
  const auto* item = v.scene().messageItem();
  const QRectF message = item->deviceTransform(v.view.viewportTransform()).mapRect(item->boundingRect());
  QTest::mouseRelease(v.viewport(), Qt::LeftButton, Qt::NoModifier, far);
  CHECK(image.save("/tmp/linkwright_canvas_refused.png"));
  CHECK(countNear(image, ui::colors().refusal) > 30);
  CHECK(QRectF(v.viewport()->rect()).contains(message));
  CHECK(countNear(grabView(v), ui::colors().refusal) == 0);
}

TEST_CASE("zoomed in, pins and links keep their pixel size", "[canvas][render]") {
  ShownView v;
  const int normal = countNear(grabView(v), ui::colors().pinOutline);
  v.wheel(v.pixelOf(v.point(fourbar::kB)), 20);  // 38 times closer
  const QImage image = grabView(v);
  CHECK(image.save("/tmp/linkwright_canvas_zoomed.png"));
  // Fewer pins are in view, but none has grown: outline pixels do not multiply.
  CHECK(countNear(image, ui::colors().pinOutline) <= normal);
  CHECK(countNear(image, ui::linkColor(0)) > 100);
}

TEST_CASE("QGraphicsView::render, as the image export uses it, draws the labels too", "[canvas][render]") {
  k::Design metres =
      k::fourBarDesign({0.06, 0.025, 0.07, 0.045}, k::Branch::Open, "m", k::CouplerPointSpec{0.03, 0.02}).value();
  ShownView v(metres);
  v.view.setShowVelocityArrows(true);
  const QImage shown = grabView(v);
  QImage rendered(v.viewport()->size(), QImage::Format_ARGB32);
  rendered.fill(Qt::white);
  QPainter painter(&rendered);
  painter.setRenderHint(QPainter::Antialiasing);
  v.view.render(&painter, QRectF(), v.viewport()->rect());
  painter.end();
  CHECK(rendered.save("/tmp/linkwright_canvas_render_metres.png"));
  const int labelsShown = countNear(shown, ui::colors().label);
  REQUIRE(labelsShown > 20);
  CHECK(countNear(rendered, ui::colors().label) >= labelsShown * 9 / 10);
  CHECK(countNear(rendered, ui::colors().velocity.darker(120)) >=
        countNear(shown, ui::colors().velocity.darker(120)) * 9 / 10);
}

TEST_CASE("the grid painted once and kept follows every zoom, pan, resize and drag", "[canvas][render]") {
  ShownView v;
  // What the view shows against what it shows once its kept grid is dropped and painted afresh
  // (refreshColors drops it, as a change of colours must).
  const auto keptEqualsFresh = [&v] {
    const QImage kept = grabView(v);
    v.view.refreshColors();
    return kept == grabView(v);
  };
  grabView(v);  // paints and keeps the grid
  CHECK(keptEqualsFresh());
  v.wheel(v.pixelOf(v.point(fourbar::kB)), 3);
  CHECK(keptEqualsFresh());
  const QPointF grabbed = v.view.mapToScene(QPoint(20, 20));
  v.drag(QPoint(20, 20), QPoint(80, 60));  // the background: a pan
  REQUIRE(v.view.mapFromScene(grabbed) != QPoint(20, 20));
  CHECK(keptEqualsFresh());
  v.view.resize(640, 520);
  CHECK(keptEqualsFresh());
  const QPoint c = v.pixelOf(v.point(fourbar::kC));
  v.drag(c, c + QPoint(6, -4));
  CHECK(keptEqualsFresh());
}
