// View ▸ Inversions… against the core (kinematics/analysis/inversions.h): each cell must name
// the class the core gives for its grounded link and animate the core's mechanism for it; one
// step moves every cell's crank; the cells follow the designer's lengths; the physical links
// keep their colours; the drawings cannot be dragged; a linkage without inversions disables the
// action; an offset slider-crank shows the core's note where an inversion cannot be built.
#include "ui/classroom/inversions_window.h"
#include "ui/animation/crank_animator.h"
#include "ui/canvas/feasible_range_item.h"
#include "ui/canvas/link_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/classroom/inversion_cell_panel.h"
#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"

#include "kinematics/analysis/inversions.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/slider_crank.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QAction>
#include <QApplication>
#include <QTest>

#include <cmath>
#include <utility>
#include <vector>

using namespace linkwright;
using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

k::FourBarLengths lengthsIn(const MechanismDocument& document) {
  const auto f = k::asFourBar(document.mechanism());
  REQUIRE(f);
  return f->lengths;
}

std::vector<k::FourBarInversion> coreInversions(const k::FourBarLengths& lengths) {
  const auto inversions = k::fourBarInversions(lengths);
  REQUIRE(inversions);
  return *inversions;
}

// Each cell's document holds the core's inversion: the same lengths in the same roles, and
// the core's class name under the cell's title.
void checkCellsMatchCore(const InversionsWindow& window, const k::FourBarLengths& original) {
  const auto expected = coreInversions(original);
  REQUIRE(expected.size() == InversionsWindow::kCells);
  for (int i = 0; i < InversionsWindow::kCells; ++i) {
    const InversionCellPanel* cell = window.cell(i);
    const auto& inv = expected[static_cast<std::size_t>(i)];
    INFO("cell " << i << ": ground the " << k::toString(inv.grounded));
    CHECK(cell->title().toStdString() == "Ground: " + std::string(k::toString(inv.grounded)));
    CHECK(cell->className().toStdString() == inv.name);
    REQUIRE(cell->hasLinkage());
    const k::FourBarLengths got = lengthsIn(*cell->document());
    CHECK(got.frame == Approx(inv.lengths.frame));
    CHECK(got.crank == Approx(inv.lengths.crank));
    CHECK(got.coupler == Approx(inv.lengths.coupler));
    CHECK(got.rocker == Approx(inv.lengths.rocker));
  }
}

k::Design sliderCrankDesign(const k::SliderCrankGeometry& geometry) {
  k::Design d;
  d.kind = "slider-crank";
  d.mechanism = k::makeSliderCrank(geometry).value();
  return d;
}

}  // namespace

TEST_CASE("the thesis crank-rocker's four inversions are the core's, class by class", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  REQUIRE(window.inversionsAction()->isEnabled());
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  CHECK(inversions->isVisible());
  checkCellsMatchCore(*inversions, lengthsIn(*window.document()));
  // The thesis chain is Grashof with the crank shortest: two crank-rockers, a drag link and a
  // double-rocker, in the core's order (frame, crank, coupler, rocker grounded).
  CHECK(inversions->cell(0)->className() == "crank-rocker");
  CHECK(inversions->cell(1)->className() == "double-crank (drag link)");
  CHECK(inversions->cell(2)->className() == "crank-rocker");
  CHECK(inversions->cell(3)->className() == "double-rocker (Grashof)");
  CHECK(inversions->headingText().contains("Grashof"));
  // Asked again, the same window comes forward.
  CHECK(window.showInversions() == inversions);
}

TEST_CASE("a physical link keeps its colour in every inversion", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  const k::FourBarLengths original = lengthsIn(*window.document());
  // The thesis lengths are all different, so a length says which physical link a bar is.
  const std::pair<double, QColor> colours[] = {{original.crank, linkColor(0)},
                                               {original.coupler, linkColor(1)},
                                               {original.rocker, linkColor(2)},
                                               {original.frame, linkColor(3)}};
  const auto colourOf = [&](double length) {
    std::vector<QColor> found;
    for (const auto& [l, c] : colours)
      if (std::abs(l - length) <= 1e-9 * l) found.push_back(c);
    REQUIRE(found.size() == 1);
    return found.front();
  };
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  for (int i = 0; i < InversionsWindow::kCells; ++i) {
    const InversionCellPanel* cell = inversions->cell(i);
    const k::FourBarLengths got = lengthsIn(*cell->document());
    const auto* scene = static_cast<const LinkageScene*>(cell->view()->linkageScene());
    const std::pair<k::LinkId, double> bars[] = {
        {k::fourbar::kCrank, got.crank}, {k::fourbar::kCoupler, got.coupler}, {k::fourbar::kRocker, got.rocker}};
    for (const auto& [link, length] : bars) {
      INFO("cell " << i << ", link " << link.index << " of length " << length);
      const LinkItem* item = scene->linkItem(link);
      REQUIRE(item != nullptr);
      CHECK(item->pen().color() == colourOf(length));
    }
  }
}

TEST_CASE("one step moves every inversion's crank, play and pause drive all four", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  std::vector<double> before;
  for (int i = 0; i < InversionsWindow::kCells; ++i) before.push_back(inversions->cell(i)->document()->crankAngle());
  inversions->step();
  for (int i = 0; i < InversionsWindow::kCells; ++i) {
    INFO("cell " << i);
    CHECK(inversions->cell(i)->document()->crankAngle() != Approx(before[static_cast<std::size_t>(i)]).margin(1e-9));
  }
  inversions->play();
  for (int i = 0; i < InversionsWindow::kCells; ++i) CHECK(inversions->cell(i)->animator()->isPlaying());
  inversions->pause();
  for (int i = 0; i < InversionsWindow::kCells; ++i) CHECK_FALSE(inversions->cell(i)->animator()->isPlaying());
}

TEST_CASE("a double-rocker inversion rocks between the ends of its range", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  MechanismDocument* rocker = inversions->cell(3)->document();  // the rocker grounded
  const k::InputRange& range = rocker->analysis().inputRange;
  REQUIRE_FALSE(range.fullRotation);
  REQUIRE_FALSE(range.ranges.empty());
  // Its reach is stated above the drawing, not across it; a crank that turns fully has none.
  const auto* scene = static_cast<const LinkageScene*>(inversions->cell(3)->view()->linkageScene());
  CHECK(inversions->cell(3)->detail().contains(scene->feasibleRangeItem()->labelText()));
  CHECK(inversions->cell(3)->detail().contains("can reach"));
  CHECK_FALSE(inversions->cell(0)->detail().contains("can reach"));
  // Twelve 30° steps would take a turning crank round once; this one must stay in its range
  // and turn back at least once.
  bool turnedBack = false;
  for (int i = 0; i < 12; ++i) {
    inversions->step();
    CHECK(range.contains(rocker->crankAngle(), 1e-9));
    turnedBack = turnedBack || inversions->cell(3)->animator()->direction() < 0;
  }
  CHECK(turnedBack);
}

TEST_CASE("the inversions follow the designer's lengths", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  const int rebuilds = inversions->rebuilds();
  // A longer rocker: S + L = 25 + 70 = 95 < P + Q = 60 + 50 = 110, still Grashof, other lengths.
  const k::FourBarLengths longer{60.0, 25.0, 70.0, 50.0};
  REQUIRE_FALSE(window.document()->edit(testing::withLengths(window.document()->design(), longer), "rocker"));
  CHECK(inversions->rebuilds() > rebuilds);
  checkCellsMatchCore(*inversions, longer);
  CHECK(lengthsIn(*inversions->cell(0)->document()).rocker == Approx(50.0));
  // A non-Grashof chain: every inversion becomes a triple-rocker.
  const k::FourBarLengths nonGrashof{60.0, 45.0, 70.0, 50.0};
  REQUIRE_FALSE(window.document()->edit(testing::withLengths(window.document()->design(), nonGrashof), "crank"));
  checkCellsMatchCore(*inversions, nonGrashof);
  for (int i = 0; i < InversionsWindow::kCells; ++i)
    CHECK(inversions->cell(i)->className() == "triple-rocker (non-Grashof)");
}

TEST_CASE("the inversions' drawings cannot be dragged", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  REQUIRE(QTest::qWaitForWindowExposed(inversions));
  InversionCellPanel* cell = inversions->cell(0);
  LinkageView* view = cell->view();
  CHECK(view->isReadOnly());
  MechanismDocument* document = cell->document();
  const auto dragB = [&] {
    const Eigen::Vector2d b = document->pose().position[k::fourbar::kB.index];
    const QPoint press = view->mapFromScene(QPointF(b.x(), b.y()));
    QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, press);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(view->viewport(), press + QPoint(3 * i, 3 * i));
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, press + QPoint(15, 15));
  };
  const k::Design before = document->design();
  dragB();
  CHECK(document->design() == before);
  CHECK(document->undoStack()->count() == 0);
  // The same drag on an editable view does edit: the check above can fail.
  view->setReadOnly(false);
  dragB();
  CHECK(document->undoStack()->count() == 1);
}

TEST_CASE("a six-bar has no inversions: the action is disabled and says why", "[classroom][inversions]") {
  MainWindow window;
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  CHECK(window.inversionsAction()->isEnabled());
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  window.newDocument(*k::designForExample("stephenson-ii"));
  CHECK_FALSE(window.inversionsAction()->isEnabled());
  CHECK(window.inversionsAction()->toolTip().contains("four-bars and slider-cranks only"));
  CHECK(window.showInversions() == nullptr);
  // The window that was open says why too, and stops.
  CHECK(inversions->headingText().contains("four-bars and slider-cranks only"));
  CHECK_FALSE(inversions->isPlaying());
  window.newDocument(*k::designForExample("thesis-crank-rocker"));
  CHECK(window.inversionsAction()->isEnabled());
  checkCellsMatchCore(*inversions, lengthsIn(*window.document()));
}

TEST_CASE("an offset slider-crank shows the core's note where an inversion cannot be built",
          "[classroom][inversions]") {
  const k::SliderCrankGeometry geometry{46.0, 150.0, 12.0, false};
  const auto expected = k::sliderCrankInversions(geometry);
  REQUIRE(expected);
  MainWindow window;
  window.newDocument(sliderCrankDesign(geometry));
  REQUIRE(window.inversionsAction()->isEnabled());
  InversionsWindow* inversions = window.showInversions();
  REQUIRE(inversions != nullptr);
  CHECK(inversions->headingText().contains("offset 12"));
  for (int i = 0; i < InversionsWindow::kCells; ++i) {
    const auto& inv = (*expected)[static_cast<std::size_t>(i)];
    const InversionCellPanel* cell = inversions->cell(i);
    INFO("cell " << i << ": ground the " << k::toString(inv.grounded));
    CHECK(cell->className().toStdString() == inv.name);
    CHECK(cell->hasLinkage() == inv.mechanism.has_value());
    if (inv.mechanism) {
      CHECK(cell->document()->mechanism().points.size() == inv.mechanism->points.size());
      CHECK(cell->note().isEmpty());
    } else {
      CHECK(cell->note().contains(QString::fromStdString(inv.note)));
      CHECK(cell->note().contains("offset 12"));
    }
  }
  // The ones the core cannot build are the slotted ones, grounding the crank and the rod.
  CHECK_FALSE(inversions->cell(1)->hasLinkage());
  CHECK_FALSE(inversions->cell(2)->hasLinkage());
  // Without the offset all four are built and animate.
  window.newDocument(sliderCrankDesign({46.0, 150.0, 0.0, false}));
  for (int i = 0; i < InversionsWindow::kCells; ++i) CHECK(inversions->cell(i)->hasLinkage());
  std::vector<double> before;
  for (int i = 0; i < InversionsWindow::kCells; ++i) before.push_back(inversions->cell(i)->document()->crankAngle());
  inversions->step();
  for (int i = 0; i < InversionsWindow::kCells; ++i)
    CHECK(inversions->cell(i)->document()->crankAngle() != Approx(before[static_cast<std::size_t>(i)]).margin(1e-9));
}
