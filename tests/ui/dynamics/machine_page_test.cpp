// The Forces tab's Flywheel and motor page: the core's machine request for the fields typed (the
// figures the CLI and Python give, to the bit), run on the worker pool, the speed run in time
// with the flywheel drawn between the limits Cs sets, the fields' ranges and tooltips the
// request's, nothing computed off screen, and nothing left from an earlier design or field value.
#include "ui/plots/machine_page.h"

#include "ui/number_text.h"

#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/force_plot_panel.h"

#include "kinematics/design/design.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/model/units.h"

#include <QDoubleSpinBox>
#include <QTabWidget>

#include "tests/support/catch.h"

#include <algorithm>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

struct ShownMachine {
  MechanismDocument doc;
  ForceResults forces{&doc};
  ForcePlotPanel panel{&doc, &forces};
  MachinePage& page = *panel.machinePage();

  explicit ShownMachine(const k::Design& design) {
    forces.setThreading(ForceResults::Threading::GuiThread);
    doc.reset(design);
    forces.setEnabled(true);
    panel.resize(1000, 700);
    panel.show();
  }
  void showPage() {
    panel.pages()->setCurrentWidget(&page);
    page.waitForFigures();
  }
  void refresh() {
    page.refresh();
    page.waitForFigures();
  }
};

// (max − min) / mean of a curve's y.
double spread(const QList<QPointF>& points) {
  const auto [low, high] = std::minmax_element(points.begin(), points.end(),
                                               [](const QPointF& a, const QPointF& b) { return a.y() < b.y(); });
  return (high->y() - low->y()) / (0.5 * (high->y() + low->y()));
}

}  // namespace

TEST_CASE("the flywheel page shows the core's duty and the speed run in time within Cs", "[forces][machine]") {
  const k::Design design = *k::designForExample("funsho-fourbar");
  ShownMachine shown(design);
  MachinePage& page = shown.page;
  CHECK(page.figuresText().isEmpty());  // nothing computed before the page is shown
  shown.showPage();
  const QString text = page.figuresText();
  INFO(text.toStdString());
  // The core's request, as linkwright-cli machine --cs 0.05 makes it, gives these figures.
  const auto request = k::machineRequest({{"cs", 0.05}}, k::FrontEnd::Cli).value();
  const auto run =
      k::runMachine(design.mechanism, design.dynamics, k::machineDefaultsOf(k::sweepGridOf(design)), request).value();
  const k::MachineDuty& duty = run.duty;
  CHECK(text.contains(QStringLiteral("read at %1 samples; every figure within 1e-9 relative").arg(run.samples)));
  for (const k::DutyFigure& f : k::dutyFigures(duty, request.duty))
    CHECK(text.contains(
        QStringLiteral("%1: %2 %3")
            .arg(QString::fromStdString(f.label), numberText(f.value, 'g', 8), QString::fromStdString(f.unit))));
  CHECK(text.contains(QStringLiteral("flywheel for Cs 0.05: %1 kg·m²").arg(numberText(*duty.flywheelInertia, 'g', 8))));
  CHECK_FALSE(text.contains("nan"));
  // The fields are the request's: its range and its help.
  CHECK(page.efficiencyField()->minimum() == 0.01);
  CHECK(page.efficiencyField()->toolTip().contains("from 0.01 to 1"));
  CHECK(page.ratedSpeedField()->maximum() == k::kMaxRatedRpm);

  // The run in time, as the core ran it, varies by Cs within 2 %; the limits are ω̄ (1 ± Cs/2).
  const QList<QPointF> speed = page.speedChart()->samples(0);
  REQUIRE(static_cast<std::size_t>(speed.size()) == duty.flywheelRun->speed.size());
  CHECK(speed.front().y() == duty.flywheelRun->speed.front());
  CHECK(speed.front().x() == Approx(k::radToDeg(duty.flywheelRun->angle.front())));
  CHECK(spread(speed) == Approx(0.05).epsilon(0.02));
  CHECK(page.speedChart()->samples(1).front().y() == Approx(duty.flywheelRun->meanSpeed * 0.975));
  CHECK(page.speedChart()->samples(2).front().y() == Approx(duty.flywheelRun->meanSpeed * 1.025));

  // A tighter Cs: a new flywheel and a run that varies by it.
  page.speedFluctuationField()->setValue(0.02);
  shown.refresh();
  CHECK(page.figuresText().contains("flywheel for Cs 0.02"));
  CHECK(spread(page.speedChart()->samples(0)) == Approx(0.02).epsilon(0.02));

  // A motor rating gives a verdict; clearing it takes the verdict away.
  page.ratedTorqueField()->setValue(0.01);
  page.ratedSpeedField()->setValue(1000.0);
  shown.refresh();
  CHECK(page.figuresText().contains("Verdict: too weak"));
  page.ratedTorqueField()->setValue(0.0);
  page.ratedSpeedField()->setValue(0.0);
  shown.refresh();
  CHECK_FALSE(page.figuresText().contains("Verdict"));
}

TEST_CASE("the flywheel page follows the design, and only while shown", "[forces][machine]") {
  ShownMachine shown(*k::designForExample("funsho-fourbar"));
  MachinePage& page = shown.page;
  shown.showPage();
  CHECK(page.figuresText().contains("One crank turn at 100 rad/s"));

  // Another page chosen: an edit is not computed until the page is shown again.
  shown.panel.pages()->setCurrentIndex(0);
  k::Design faster = shown.doc.design();
  faster.omega = 50.0;
  REQUIRE_FALSE(shown.doc.edit(faster, "omega"));
  CHECK(page.figuresText().contains("One crank turn at 100 rad/s"));
  shown.showPage();
  CHECK(page.figuresText().contains("One crank turn at 50 rad/s"));

  // On screen, a new design is computed once it settles; an actuator-driven one is refused with
  // the core's reason and no chart left from the four-bar.
  k::Design boom = *k::designForExample("excavator-boom");
  boom.dynamics.links = {{"boom", 50.0, std::nullopt, std::nullopt}};
  shown.doc.reset(boom);
  shown.refresh();
  CHECK(page.figuresText().contains("for a crank turning at a steady speed"));
  CHECK_FALSE(page.speedChart()->isVisible());
}

TEST_CASE("the flywheel page drops an answer whose design was replaced while it ran", "[forces][machine]") {
  ShownMachine shown(*k::designForExample("funsho-fourbar"));
  MachinePage& page = shown.page;
  shown.showPage();
  // A run for ω = 50 is started, and before it lands the design goes to ω = 20: the page shows
  // the answer for 20 only, never the one for 50.
  k::Design design = shown.doc.design();
  design.omega = 50.0;
  REQUIRE_FALSE(shown.doc.edit(design, "omega"));
  page.refresh();
  design.omega = 20.0;
  REQUIRE_FALSE(shown.doc.edit(design, "omega"));
  page.waitForFigures();  // nothing pending: the change dropped it
  CHECK_FALSE(page.figuresText().contains("at 50 rad/s"));
  shown.refresh();
  CHECK(page.figuresText().contains("One crank turn at 20 rad/s"));
}
