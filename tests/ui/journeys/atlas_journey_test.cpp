// View ▸ Atlas… as a person uses it (ui/classroom/atlas_window.h): opened from the menu, a grid
// typed into its fields, the cells arriving from the worker; each cell draws the core's coupler
// path of its four-bar (coupler_atlas.h, the solver's samples), the filter keeps exactly the
// cells the core's filter keeps, a click makes the cell's four-bar the design, and Ctrl+Z in the
// atlas window (the designer's Undo) puts the design back. A bad ratio is refused with the core's sentence, keeping the
// grid shown; the same grid typed again is drawn from the cache at once.

#include "tests/ui/journeys/journey.h"

#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/classroom/atlas_cell_cache.h"
#include "ui/classroom/atlas_cell_view.h"
#include "ui/classroom/atlas_window.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/model/recognise.h"

#include "tests/support/catch.h"

#include <QApplication>
#include <QCheckBox>
#include <QFontMetrics>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

using linkwright::test::Journey;
using namespace linkwright::ui;
namespace k = linkwright::kinematics;

TEST_CASE("the atlas draws the core's coupler curves, filters them and loads one as the design", "[journey][atlas]") {
  Journey journey;
  journey.menu({"View", "Atlas"});
  auto* atlas = journey.window().findChild<AtlasWindow*>();
  REQUIRE(atlas != nullptr);
  REQUIRE(atlas->isVisible());
  REQUIRE(QTest::qWaitForWindowActive(atlas));
  // Hoeken's linkage is among them: coupler 2.5, rocker 2.5, frame 2, P 2 along.
  const std::array<QString, 5> grid{"2.5", "2,2.5", "2,3", "0.5,2", "0,0.4"};
  for (int i = 0; i < 5; ++i) journey.type(atlas->axisField(i), grid[static_cast<std::size_t>(i)]);
  REQUIRE(atlas->cells().size() == 16);
  REQUIRE(QTest::qWaitFor([&] { return atlas->complete(); }, 30000));
  CHECK(atlas->statusText() == "16 cells; 16 shown");

  // Every cell draws its four-bar's coupler path: the core's samples, inside the drawing.
  std::vector<k::AtlasCell> cells;
  for (const AtlasCellView* view : atlas->cells()) {
    const k::AtlasCell core = k::computeAtlasCell(view->key()).value();
    CAPTURE(view->index());
    REQUIRE(view->drawnCurve().size() == static_cast<qsizetype>(core.curve.size()));
    for (std::size_t j = 0; j < core.curve.size(); ++j) {
      const QPointF drawn = view->drawnCurve()[static_cast<qsizetype>(j)];
      REQUIRE(drawn == QPointF(core.curve.point[j].x(), core.curve.point[j].y()));
      REQUIRE(QRectF(view->rect()).contains(view->modelToWidget().map(drawn)));
    }
    CHECK(view->cell()->features == core.features);
    cells.push_back(core);
  }
  journey.check("the atlas computed");

  // The filter keeps exactly the cells the core's filter keeps.
  QTest::mouseClick(atlas->filterBox(3), Qt::LeftButton);
  REQUIRE(atlas->filterBox(3)->isChecked());
  const auto kept = k::filterCells(cells, k::AtlasFilter{.straight = true});
  REQUIRE(!kept.empty());
  const auto shown = atlas->shownCells();
  REQUIRE(shown.size() == kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    CHECK(shown[i]->index() == kept[i]);
    CHECK(shown[i]->cell()->features.straight.has_value());
  }
  CHECK(atlas->statusText() == QStringLiteral("16 cells; %1 shown").arg(kept.size()));
  // Every caption fits its cell, elided where it must be (issue 57 item 9: ":usp, symmetric,
  // straight, circula" was cut at both ends); the whole of it is the tooltip's.
  for (const AtlasCellView* cell : atlas->cells()) {
    const QStringList lines = cell->shownLabel();
    REQUIRE(lines.size() == cell->label().split('\n').size());
    QFont small = cell->font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    for (const QString& line : lines) CHECK(QFontMetrics(small).horizontalAdvance(line) <= cell->width() - 4);
    if (lines.join('\n') != cell->label()) CHECK(lines.join('\n').contains(QChar(0x2026)));
  }

  // A click makes that cell's four-bar the design; Ctrl+Z in the designer puts it back.
  MechanismDocument* document = journey.window().document();
  const k::Design before = document->design();
  const double crank = k::asFourBar(before.mechanism)->lengths.crank;
  AtlasCellView* hoeken = shown.front();
  // Zoomed in on the design first: the cell's linkage is fitted all the same (issue 57 item 5).
  LinkageView* canvas = journey.window().canvas();
  canvas->zoomBy(6.0);
  const auto drawn = [canvas] {
    const QRectF content = dynamic_cast<LinkageScene*>(canvas->linkageScene())->contentBounds();
    return canvas->visibleRegion().contains(content);
  };
  REQUIRE_FALSE(drawn());
  QTest::mouseClick(hoeken, Qt::LeftButton, Qt::NoModifier, hoeken->rect().center());
  // At the design's speed, not the core's 1 rad/s (issue 57 item 9).
  REQUIRE(before.omega != 1.0);
  const k::Design loaded = k::atlasCellDesign(hoeken->key(), crank, before.mechanism.lengthUnit, before.omega).value();
  CHECK(document->design() == loaded);
  CHECK(document->design().omega == before.omega);
  CHECK(document->mechanism().findPoint("P").has_value());
  CHECK(drawn());
  // Ctrl+Z where the click was, in the atlas window: the design before comes back, fitted.
  REQUIRE(QApplication::activeWindow() == atlas);
  canvas->zoomBy(6.0);
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(document->design() == before);
  CHECK(drawn());
  journey.check("undo after loading an atlas cell");

  // A bad ratio is refused, naming it; the grid shown stays.
  journey.type(atlas->axisField(2), "2,-1");
  CHECK(atlas->refusal() == "Not shown: frame ratios must be between 0.001 and 1000 crank lengths (got -1)");
  CHECK(atlas->cells().size() == 16);
  // The same grid again comes from the cache: every cell at once, nothing computed.
  QSignalSpy computed(atlas->cache(), &AtlasCellCache::cellReady);
  journey.type(atlas->axisField(2), "3,2");
  CHECK(atlas->refusal().isEmpty());
  CHECK(atlas->complete());
  CHECK(computed.isEmpty());
}
