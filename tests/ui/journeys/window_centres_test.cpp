// View ▸ Instant centres in the real window draws every centre the core finds, for each
// example that has them (the crank-shaper's fifteen were missing in the designer while
// `linkwright-cli centres --example shaper` printed them).

#include "tests/ui/journeys/journey.h"

#include "ui/canvas/instant_centres_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/panels/motion_panel.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "tests/support/catch.h"

#include <QImage>
#include <QSlider>
#include <QTest>

#include <cmath>
#include <string>

using namespace linkwright;
namespace k = kinematics;

TEST_CASE("View ▸ Instant centres in the window draws the core's centres, the shaper's included",
          "[ui][window][journey][centres]") {
  const std::string example = GENERATE("thesis-crank-rocker", "shaper", "watt-ii", "ls3-engine");
  CAPTURE(example);
  test::Journey journey(QSize(1366, 768));
  ui::MainWindow& window = journey.window();
  // As the designer runs (app/main.cpp): slow sweeps in a worker.
  window.document()->setSweepThreading(ui::DisplaySweeper::Threading::Adaptive);
  journey.example(example);
  journey.menu({"View", "Instant centres and centrodes"});
  // The crank moved to 30° with the Motion bar's slider (tenths of a degree).
  window.motionPanel()->positionSlider()->setValue(300);
  journey.check("centres at 30°");
  const auto* scene = dynamic_cast<ui::LinkageScene*>(window.canvas()->linkageScene());
  REQUIRE(scene != nullptr);
  const ui::InstantCentresItem& item = *scene->instantCentresItem();
  const auto expected = k::instantCentres(window.document()->mechanism(), window.document()->pose());
  REQUIRE(expected);
  CAPTURE(item.reason().toStdString());
  REQUIRE(item.centres().has_value());
  CHECK(item.centres()->centres.size() == expected->centres.size());
  CHECK(*item.centres() == *expected);
  const QRectF bounds = item.boundingRect();
  CAPTURE(bounds.x(), bounds.y(), bounds.width(), bounds.height());
  CHECK(std::isfinite(bounds.width()));
  CHECK(std::isfinite(bounds.height()));
  CHECK(bounds.width() < 1e7);
  // Drawn: the centres' colour appears on the canvas as a person sees it.
  const QImage shot = window.canvas()->viewport()->grab().toImage();
  int marked = 0;
  for (int y = 0; y < shot.height(); ++y)
    for (int x = 0; x < shot.width(); ++x)
      if (shot.pixelColor(x, y) == ui::colors().centre) ++marked;
  CHECK(marked > 50);
}
