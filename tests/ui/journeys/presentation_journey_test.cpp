// A teacher turns presentation mode on and off (F11, F11) before a lecture, then opens the LS3
// engine: every chart showed a stray bold "crank angle [deg]" at its top-left. Qt Charts draws
// a hidden axis's title when the title is shown again, unplaced; the axes are drawn by items of
// ours (ui/plots/plot_axes.h), so no text item of Qt's may show an axis title.

#include "tests/ui/journeys/journey.h"

#include "ui/panels/dynamics_panel.h"
#include "ui/panels/mass_table.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include "tests/support/catch.h"

#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QScatterSeries>
#include <QValueAxis>

using namespace linkwright;

namespace {

// Qt's own text items that show an axis title of any chart of the Kinematics tab.
int strayAxisTitles(ui::MainWindow& window) {
  int stray = 0;
  for (ui::QuantityChartView* view : window.plots()->findChildren<ui::QuantityChartView*>()) {
    if (view->isHidden()) continue;
    const QString title = view->xAxis()->titleText();
    for (QGraphicsItem* item : view->scene()->items()) {
      const auto* text = dynamic_cast<const QGraphicsTextItem*>(item);
      if (text != nullptr && text->isVisible() && !title.isEmpty() && text->toPlainText().contains(title)) ++stray;
    }
  }
  return stray;
}

}  // namespace

TEST_CASE("presentation mode on and off, then another example: no stray axis titles", "[journey][presentation]") {
  test::Journey journey;
  journey.key(Qt::Key_F11);
  CHECK(journey.window().presentationMode());
  CHECK(strayAxisTitles(journey.window()) == 0);
  journey.key(Qt::Key_F11);
  CHECK_FALSE(journey.window().presentationMode());
  journey.check("F11, F11");
  CHECK(strayAxisTitles(journey.window()) == 0);
  for (const char* example : {"ls3-engine", "thesis-crank-rocker", "watt-ii"}) {
    journey.example(example);
    journey.check(std::string("Examples ▸ ") + example);
    CHECK(strayAxisTitles(journey.window()) == 0);
  }
}

TEST_CASE("in presentation mode the limit labels grow and the mass table keeps its rows", "[journey][presentation]") {
  test::Journey journey;
  journey.example("funsho-fourbar");
  const QScatterSeries* limits = journey.window().plots()->limitMarkers()->points();
  REQUIRE(limits->isVisible());
  const double before = limits->pointLabelsFont().pointSizeF();
  journey.menu({"View", "Presentation mode"});
  REQUIRE(journey.window().presentationMode());
  // "limit" grows with the axes' text.
  CHECK(limits->pointLabelsFont().pointSizeF() == Approx(1.6 * before).epsilon(0.02));
  journey.menu({"View", "Forces and masses"});
  // The Links table shows its header and its rows (it was squeezed to a sliver).
  const ui::MassTable* table = journey.window().findChild<ui::DynamicsPanel*>()->linkTable();
  REQUIRE(table->rowCount() >= 3);
  for (int row = 0; row < ui::MassTable::kRowsAlwaysShown; ++row) {
    const QRect cell = table->visualRect(table->model()->index(row, 0));
    CAPTURE(row, cell.top(), cell.bottom(), table->viewport()->height(), table->minimumSizeHint().height());
    CHECK(cell.bottom() < table->viewport()->height());
    CHECK(cell.top() >= 0);
  }
  journey.menu({"View", "Presentation mode"});
  CHECK(limits->pointLabelsFont().pointSizeF() == Approx(before));
  journey.check("presentation off");
}
