// The shaking force as a person looks for it: a linkage with masses, View ▸ Forces and masses,
// a click on the Shaking tab, then a typed crank length, the polar diagram of the shaking force
// picked with the keyboard, and another example without masses. After every step the
// journeys' invariants hold, and the charts hold the core's shaking force of the design on
// screen, never an earlier one's.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/force_plot_panel.h"
#include "ui/plots/polar_load_view.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "tests/support/catch.h"

#include <QAction>
#include <QChart>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QInputDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>

using namespace linkwright;

namespace {

// Checks the chart's |F| curve point by point against the core's for the design on screen,
// solved afresh at each plotted crank angle (a pose and its forces, not the window's sweep).
void checkShakingCurve(ui::MainWindow& window) {
  const kinematics::Design& d = window.document()->design();
  const QList<QPointF> plotted = window.forcePlots()->shakingChart()->samples(2);
  REQUIRE(plotted.size() > 100);
  for (const QPointF& p : plotted) {
    const auto pose = kinematics::solvePose(d.mechanism, {kinematics::degToRad(p.x()), d.omega, d.alpha});
    REQUIRE(pose.ok());
    const auto forces = kinematics::forcesAtPose(d.mechanism, d.dynamics, *pose);
    REQUIRE(forces.ok());
    CHECK(p.y() == Approx(forces->shakingForce.norm()).epsilon(1e-9).margin(1e-9));  // N: round-off once balanced
  }
}

void clickTab(QTabWidget* pages, int index) {
  QTabBar* bar = pages->tabBar();
  QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(index).center());
}

}  // namespace

TEST_CASE("look at a linkage's shaking force, change the linkage, look at its polar diagram", "[journey][forces]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.example("funsho-fourbar");
  journey.menu({"View", "Forces and masses"});
  journey.check("Examples ▸ funsho-fourbar, View ▸ Forces and masses");
  ui::ForcePlotPanel* forces = window.forcePlots();
  clickTab(forces->pages(), 1);
  journey.settle();
  REQUIRE(forces->pages()->currentIndex() == 1);
  CHECK(forces->shakingChart()->isVisible());
  CHECK(forces->shakingPeakText().startsWith("Peak shaking force 179.4 N at crank"));
  checkShakingCurve(window);
  journey.check("the Shaking tab");

  journey.type(window.dimensionsPanel()->editor(kinematics::ParameterSlot::CrankLength), "12");
  CHECK(window.document()->fourBar()->lengths.crank == 12.0);
  checkShakingCurve(window);  // the new crank's, not the old one's
  CHECK_FALSE(forces->shakingPeakText().startsWith("Peak shaking force 179.4 N"));
  journey.check("Crank 12");

  clickTab(forces->pages(), 2);
  QComboBox* of = forces->jointSelector();
  of->setFocus();
  journey.key(Qt::Key_End);
  CHECK(of->currentText() == "the shaking force");
  CHECK(forces->polarView()->chart()->title() == "Shaking force on the frame");
  CHECK(forces->polarView()->pointCount() == forces->shakingChart()->samples(2).size());
  journey.check("the polar diagram of the shaking force");

  // No masses: nothing of funsho's may stay. The edited design is not kept.
  journey.whenDialogOpens<QMessageBox>([](QMessageBox* ask) { ask->button(QMessageBox::Discard)->click(); });
  journey.example("thesis-crank-rocker");
  CHECK_FALSE(forces->shakingChart()->isVisibleTo(&window));
  CHECK_FALSE(forces->polarView()->isVisibleTo(&window));
  CHECK(forces->statusText().contains("no masses"));
  journey.check("Examples ▸ thesis-crank-rocker");
}

TEST_CASE("balance a four-bar's shaking force from the Edit menu, see it gone, undo it", "[journey][forces][balance]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  CHECK_FALSE(window.balanceAction()->isEnabled());  // the thesis four-bar has no masses
  CHECK(window.balanceAction()->toolTip().contains("there are no masses to balance"));
  journey.example("funsho-fourbar");
  journey.menu({"View", "Forces and masses"});
  ui::ForcePlotPanel* forces = window.forcePlots();
  clickTab(forces->pages(), 1);
  journey.check("funsho's Shaking tab");
  REQUIRE(window.balanceAction()->isEnabled());
  const kinematics::Design before = window.document()->design();

  journey.menu({"Edit", "Balance the shaking force"});
  CHECK(window.statusBar()->currentMessage().startsWith("Balanced (Ctrl+Z undoes): shaking force peak 179.4 → "));
  double peak = 0.0;
  for (const QPointF& p : forces->shakingChart()->samples(2)) peak = std::max(peak, p.y());
  CHECK(peak <= 1e-9 * 179.4);
  checkShakingCurve(window);
  // Before and after: the dashed curves are the unbalanced design's, solved afresh.
  REQUIRE(forces->showsBefore());
  const QList<QPointF> was = forces->shakingChart()->samples(3);
  REQUIRE(was.size() > 100);
  double wasPeak = 0.0;
  for (const QPointF& p : was) wasPeak = std::max(wasPeak, p.y());
  CHECK(wasPeak == Approx(179.4).epsilon(1e-3));
  for (const QPointF& p : {was.front(), was[was.size() / 3]}) {
    const auto pose =
        kinematics::solvePose(before.mechanism, {kinematics::degToRad(p.x()), before.omega, before.alpha});
    const auto unbalanced = kinematics::forcesAtPose(before.mechanism, before.dynamics, *pose);
    CHECK(p.y() == Approx(unbalanced->shakingForce.norm()).epsilon(1e-9));
  }
  CHECK(forces->shakingPeakText().contains("Before balancing (dashed, the best samples): 179.4 N"));
  CHECK(forces->torqueChart()->samples(1).size() == forces->torqueChart()->samples(0).size());
  CHECK(forces->shakingMomentChart()->samples(1).size() > 100);
  CHECK(window.document()->design().dynamics.links.size() == 3);  // counterweights joined to their links
  CHECK_FALSE(window.balanceAction()->isEnabled());               // nothing left to balance
  journey.check("Edit ▸ Balance the shaking force");

  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(window.document()->design() == before);
  CHECK(forces->shakingPeakText().startsWith("Peak shaking force 179.4 N"));
  // Nothing from the balanced design is left: no dashed curves, no "before" in the peaks.
  CHECK_FALSE(forces->showsBefore());
  CHECK_FALSE(forces->shakingPeakText().contains("Before"));
  CHECK(forces->shakingChart()->samples(3).isEmpty());
  checkShakingCurve(window);
  CHECK(window.balanceAction()->isEnabled());
  journey.check("Ctrl+Z");
}

TEST_CASE("balance the driving torque by a spring from the Edit menu, see before and after, undo it",
          "[journey][forces][springs]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  CHECK_FALSE(window.springBalanceAction()->isEnabled());  // the thesis four-bar has no masses
  journey.example("funsho-fourbar");
  journey.menu({"View", "Forces and masses"});
  REQUIRE(window.springBalanceAction()->isEnabled());
  const kinematics::Design before = window.document()->design();
  journey.check("funsho's Forces tab");

  journey.whenDialogOpens<QInputDialog>([](QInputDialog* dialog) {
    dialog->setTextValue("rocker");
    dialog->accept();
  });
  journey.menu({"Edit", "Balance the torque by a spring"});
  const kinematics::Design& after = window.document()->design();
  REQUIRE(after.dynamics.loads.springs.size() == 1);
  CHECK(after.dynamics.loads.springs.front().first.link == "rocker");
  CHECK(after.mechanism.points.size() == before.mechanism.points.size() + 2);
  CHECK(window.statusBar()->currentMessage().contains("driving torque RMS 0.6709 → 0.3387 N·m"));
  // The torque before (dashed) beside the torque now, whose RMS is the one announced.
  ui::ForcePlotPanel* forces = window.forcePlots();
  REQUIRE(forces->showsBefore());
  const QList<QPointF> now = forces->torqueChart()->samples(0), was = forces->torqueChart()->samples(1);
  REQUIRE(now.size() == was.size());
  double peakNow = 0.0, peakWas = 0.0;
  for (qsizetype i = 0; i < now.size(); ++i) {
    peakNow = std::max(peakNow, std::abs(now[i].y()));
    peakWas = std::max(peakWas, std::abs(was[i].y()));
  }
  CHECK(peakNow < peakWas);
  journey.check("Edit ▸ Balance the torque by a spring");

  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(window.document()->design() == before);
  CHECK_FALSE(forces->showsBefore());
  CHECK(forces->torqueChart()->samples(1).isEmpty());
  journey.check("Ctrl+Z");
}
