// View ▸ Tolerances… against the core (kinematics/tune/tolerance_*.h): the band chart holds
// the Monte-Carlo result's nominal, lowest and highest curves, the sensitivity chart the exact
// derivatives, the summary its figures; an edit drops them at once and the study is redone for
// the new design; a tolerance the core refuses leaves the window saying why with nothing drawn.
#include "ui/plots/tolerance_window.h"

#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"
#include "ui/plots/force_chart_view.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/parameters.h"
#include "kinematics/tune/tolerance_dimensions.h"
#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include "tests/support/catch.h"

#include <QChart>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QValueAxis>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

TEST_CASE("the tolerance window draws the core's band and sensitivities, and follows the design",
          "[plots][tolerance]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  ToleranceWindow window(&doc);
  window.samplesField()->setValue(200);
  window.show();
  window.refresh();
  window.waitForStudy();
  const int rocker = window.outputBox()->findText("rocker_angle_deg");
  REQUIRE(rocker >= 0);
  window.outputBox()->setCurrentIndex(rocker);

  const k::Design& design = doc.design();
  k::MonteCarloSpec spec;
  spec.tolerance = 0.05;
  spec.samples = 200;
  const auto mc = k::toleranceMonteCarlo(design.mechanism, k::designSweepSpec(design), spec).value();
  const auto& band = mc.bands[static_cast<std::size_t>(rocker)];
  // The band about the nominal: highest − nominal ≥ 0 ≥ lowest − nominal, the core's values.
  const QList<QPointF> high = window.bandChart()->samples(0), low = window.bandChart()->samples(1);
  REQUIRE(static_cast<std::size_t>(high.size()) == band.nominal.size());
  REQUIRE(low.size() == high.size());
  for (qsizetype j = 0; j < high.size(); ++j) {
    const auto i = static_cast<std::size_t>(j);
    CHECK(high[j].y() == band.high[i] - band.nominal[i]);
    CHECK(low[j].y() == band.low[i] - band.nominal[i]);
    CHECK(low[j].y() <= 0.0);
    CHECK(high[j].y() >= 0.0);
  }
  // The worst and its place are the core's, refined between the grid's inputs.
  CHECK(window.summaryText().contains("worst deviation " + numberText(band.worstDeviation, 'g', 4) + " at crank " +
                                      numberText(band.worstInput, 'f', 1) + "°"));
  // So are the first-order worst case and its place (the summary's, as the CLI prints them).
  const auto summary =
      k::sensitivitySummary(design.mechanism, k::designSweepSpec(design), k::dimensionTolerances(spec, mc.dimensions))
          .value();
  const auto r = static_cast<std::size_t>(rocker);
  CHECK(window.summaryText().contains("first-order worst case " + numberText(summary.firstOrderWorst[r], 'g', 4) +
                                      " at crank " + numberText(summary.firstOrderWorstInput[r], 'f', 1) + "°"));
  // The axes say the unit, which survives a title's shortening; the output is in the titles.
  CHECK(window.bandChart()->yAxis()->titleText() == "deviation [deg]");
  CHECK(window.sensitivityChart()->yAxis()->titleText() == "∂y/∂p [deg/mm]");
  CHECK(window.bandChart()->chart()->title().startsWith("rocker_angle_deg: "));

  const auto sens = k::sweepSensitivities(design.mechanism, k::designSweepSpec(design)).value();
  std::size_t column = 0;
  while (sens.columns[column].name != "rocker_angle_deg") ++column;
  REQUIRE(window.sensitivityChart()->samples(sens.dimensions.size() - 1).size() > 0);
  CHECK(window.sensitivityChart()->samples(0).front().y() == sens.derivative[column][0].front());

  // An edit drops the study at once (nothing from the old design stays drawn), then redoes it.
  const k::Design longer = k::fourBarDesign({60.0, 25.0, 70.0, 50.0}).value();
  REQUIRE_FALSE(doc.edit(longer, "rocker"));
  CHECK_FALSE(window.bandChart()->isVisible());
  window.refresh();
  window.waitForStudy();
  REQUIRE(window.bandChart()->isVisible());
  const auto again = k::toleranceMonteCarlo(longer.mechanism, k::designSweepSpec(longer), spec).value();
  const int index = window.outputBox()->currentIndex();
  REQUIRE(window.outputBox()->currentText() == "rocker_angle_deg");  // the chosen output kept
  const auto& newBand = again.bands[static_cast<std::size_t>(index)];
  CHECK(window.bandChart()->samples(0).back().y() == newBand.high.back() - newBand.nominal.back());

  // A tolerance as long as the crank: the core's refusal, and nothing drawn.
  window.toleranceField()->setValue(25.0);
  window.refresh();
  window.waitForStudy();
  CHECK(window.summaryText().startsWith("No tolerance study: "));
  CHECK(window.summaryText().contains("25"));
  CHECK_FALSE(window.bandChart()->isVisible());
  CHECK(window.outputBox()->count() == 0);
}

TEST_CASE("a dimension's own tolerance typed in the table is the study's, and a cell that is no number is named",
          "[plots][tolerance]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  ToleranceWindow window(&doc);
  window.samplesField()->setValue(100);
  window.show();
  window.refresh();
  window.waitForStudy();
  QTableWidget* own = window.ownTolerancesTable();
  const auto dimensions = k::toleranceDimensions(doc.design().mechanism);
  REQUIRE(own->rowCount() == static_cast<int>(dimensions.size()));
  int crank = -1;
  for (int row = 0; row < own->rowCount(); ++row) {
    CHECK(own->item(row, 0)->text().toStdString() == dimensions[static_cast<std::size_t>(row)].name);
    if (own->item(row, 0)->text() == "crank length") crank = row;
  }
  REQUIRE(crank >= 0);
  own->item(crank, 1)->setText("0.5");
  window.refresh();
  window.waitForStudy();
  const int rocker = window.outputBox()->findText("rocker_angle_deg");
  window.outputBox()->setCurrentIndex(rocker);
  k::MonteCarloSpec spec;
  spec.tolerance = 0.05;
  spec.samples = 100;
  spec.perDimension = {{"crank length", 0.5}};
  const k::Design& design = doc.design();
  const auto mc = k::toleranceMonteCarlo(design.mechanism, k::designSweepSpec(design), spec).value();
  const auto& band = mc.bands[static_cast<std::size_t>(rocker)];
  const QList<QPointF> high = window.bandChart()->samples(0);
  REQUIRE(static_cast<std::size_t>(high.size()) == band.nominal.size());
  for (qsizetype j = 0; j < high.size(); ++j)
    CHECK(high[j].y() == band.high[static_cast<std::size_t>(j)] - band.nominal[static_cast<std::size_t>(j)]);
  CHECK(window.summaryText().contains("(1 with a ± of its own)"));

  own->item(crank, 1)->setText("half a mm");
  window.refresh();
  window.waitForStudy();
  CHECK(window.summaryText() == "No tolerance study: the ± of crank length must be a number (got 'half a mm')");
  CHECK(window.bandChart()->isHidden());
}

TEST_CASE("the tolerance window's study runs off the GUI thread, and an edit or Cancel drops it",
          "[plots][tolerance]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  ToleranceWindow window(&doc);
  window.samplesField()->setValue(200);
  window.show();
  window.refresh();
  // While it runs the window says so and offers Cancel; Cancel drops the study.
  CHECK(window.summaryText().startsWith("Computing the study of 200 linkages"));
  CHECK(window.cancelButton()->isVisible());
  window.cancelButton()->click();
  window.waitForStudy();  // nothing pending: Cancel dropped it
  CHECK(window.summaryText().startsWith("The study was cancelled"));
  CHECK_FALSE(window.cancelButton()->isVisible());
  CHECK(window.outputBox()->count() == 0);
  // A study started, then the design edited before it lands: only the new design's is shown.
  window.refresh();
  k::Design longer = doc.design();
  REQUIRE(k::setParameter(longer.mechanism, k::parametersOf(longer.mechanism).front(), 62.0));
  REQUIRE_FALSE(doc.edit(longer, "frame"));
  window.waitForStudy();
  CHECK(window.outputBox()->count() == 0);  // the old design's answer was dropped
  window.refresh();
  window.waitForStudy();
  CHECK(window.outputBox()->count() > 0);
  CHECK_FALSE(window.summaryText().startsWith("Computing"));
}
