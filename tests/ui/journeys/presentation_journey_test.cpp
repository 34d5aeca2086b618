// A teacher turns presentation mode on and off (F11, F11) before a lecture, then opens the LS3
// engine: every chart showed a stray bold "crank angle [deg]" at its top-left. Qt Charts draws
// a hidden axis's title when the title is shown again, unplaced; the axes are drawn by items of
// ours (ui/plots/plot_axes.h), so no text item of Qt's may show an axis title.

#include "tests/ui/journeys/journey.h"

#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include "tests/support/catch.h"

#include <QGraphicsScene>
#include <QGraphicsTextItem>
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
