// The plots decide the displayed sweep's resolution and what it computes: its samples follow
// the plot area's width times the quality, a resize re-requests once it settles, and with
// every plot unticked only positions are swept.
#include "ui/plots/plot_panel.h"

#include "ui/plots/quality_bar.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalSpy>
#include <QTest>

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::ui;

namespace {

qsizetype plottedCount(const PlotPanel& panel, PlotQuantity q) {
  return panel.chartView(quantityKind(q))->samples(q).size();
}

int requestChanges(const QSignalSpy& spy) {
  int n = 0;
  for (const QList<QVariant>& args : spy) n += (args.first().value<Changes>() & Change::Request) ? 1 : 0;
  return n;
}

struct ShownPanel {
  MechanismDocument document;
  PlotPanel panel{&document};
  ShownPanel() {
    panel.resize(600, 700);
    panel.show();
    REQUIRE(QTest::qWaitForWindowExposed(&panel));
    panel.reportPlotWidth();
  }
  std::size_t expectedSamples() const {
    return displaySampleCount(document.quality(), std::round(panel.plotAreaWidth()), 360.0);
  }
};

}  // namespace

TEST_CASE("the displayed samples follow the plot area's width times the quality", "[plot_panel][resolution]") {
  ShownPanel v;
  const double width = v.panel.plotAreaWidth();
  REQUIRE(width > 200.0);
  CHECK(v.document.displayWidth() == std::round(width));
  CHECK(v.document.sweep().size() == v.expectedSamples());
  CHECK(v.document.sweep().size() != 721);  // not the design's grid
  // A crank-rocker assembles everywhere: one plotted point per sample.
  CHECK(plottedCount(v.panel, PlotQuantity::RockerAngle) == static_cast<qsizetype>(v.document.sweep().size()));

  SECTION("the quality box multiplies it, down to Draft's and up to Precise's floor") {
    QComboBox* box = v.panel.qualityBar()->qualityBox();
    box->setCurrentIndex(static_cast<int>(SamplingQuality::Draft));
    CHECK(v.document.quality() == SamplingQuality::Draft);
    CHECK(v.document.sweep().size() == v.expectedSamples());
    CHECK(v.document.sweep().size() == static_cast<std::size_t>(std::ceil(std::round(width) / 4.0)) + 1);
    box->setCurrentIndex(static_cast<int>(SamplingQuality::Precise));
    CHECK(v.document.sweep().size() == v.expectedSamples());
    CHECK(v.document.sweep().size() >= 3601);
    CHECK(plottedCount(v.panel, PlotQuantity::RockerAngle) == static_cast<qsizetype>(v.document.sweep().size()));
    CHECK(v.panel.qualityBar()->costText().startsWith(
        QString::number(samplesPerRevolution(v.document.sweep().size(), 360.0)) + QStringLiteral(" samples/rev")));
  }

  SECTION("a resize re-requests once, after it settles") {
    QSignalSpy spy(&v.document, &MechanismDocument::changed);
    for (int w : {700, 760, 820}) v.panel.resize(w, 700);
    CHECK(requestChanges(spy) == 0);  // not on each step of the drag
    QTest::qWait(4 * PlotPanel::kResizeSettleMs);
    v.panel.reportPlotWidth();  // whatever the timer did, the width is now reported
    CHECK(requestChanges(spy) == 1);
    CHECK(v.document.displayWidth() > std::round(width));
    CHECK(v.document.sweep().size() == v.expectedSamples());
  }
}

TEST_CASE("with every plot unticked only positions are swept", "[plot_panel][resolution]") {
  ShownPanel v;
  for (const PlotCurve& c : v.panel.curves()) v.panel.selector()->checkBox(c.quantity)->setChecked(false);
  CHECK_FALSE(v.document.request().velocities);
  CHECK_FALSE(v.document.request().accelerations);
  const auto& s = v.document.sweep();
  CHECK(s.linkOmega.empty());
  CHECK(s.linkAlpha.empty());
  CHECK(s.velocity.empty());
  CHECK(s.acceleration.empty());
  REQUIRE_FALSE(s.position.empty());
  CHECK(s.position.back().size() == s.size());
  CHECK(v.panel.plotAreaWidth() == 0.0);  // no chart shown...
  const std::size_t samples = s.size();
  v.panel.reportPlotWidth();
  CHECK(v.document.sweep().size() == samples);  // ...so the last width stands
}

TEST_CASE("off screen the plots follow no change, and catch up when shown again", "[plot_panel][resolution]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  CurveItem* rocker = panel.chartView(QuantityKind::Angle)->curveItem(PlotQuantity::RockerAngle);
  REQUIRE(rocker != nullptr);
  QSignalSpy replaced(rocker, &CurveItem::runsReplaced);
  panel.setOnScreen(false);
  namespace k = linkwright::kinematics;
  k::Design longer = doc.design();
  k::FourBarLengths lengths = doc.fourBar()->lengths;
  lengths.frame += 2.0;
  longer.mechanism = k::withFourBarLengths(longer.mechanism, *doc.fourBar(), lengths);
  REQUIRE_FALSE(doc.edit(longer, "frame"));
  doc.setCrankAngle(1.0);
  CHECK(replaced.isEmpty());  // nothing re-plotted for a tab nobody sees
  const QList<QPointF> stale = panel.chartView(QuantityKind::Angle)->samples(PlotQuantity::RockerAngle);
  panel.setOnScreen(true);
  CHECK(replaced.count() == 1);
  const QList<QPointF> now = panel.chartView(QuantityKind::Angle)->samples(PlotQuantity::RockerAngle);
  CHECK(now != stale);
  REQUIRE(now.size() == static_cast<qsizetype>(doc.sweep().size()));
  CHECK(now.back().y() == k::radToDeg(doc.sweep().linkAngle[k::fourbar::kRocker.index].back()));
  CHECK(panel.chartView(QuantityKind::Angle)->cursorX() == Approx(k::radToDeg(1.0)));
}
