// Tests the velocity-ratio and mechanical-advantage charts of ui/plots/plot_panel.h offscreen:
// they are offered for crank-driven linkages (four-bars, slider-crank, shaper, six-bars) and
// shown when ticked; their values,
// from the instant centres of each sample, equal the velocity solver's ω4/ω2 (or v/ω2) and
// its inverse; the advantage breaks at the rocker limits instead of joining +∞ to −∞; the
// limits are marked on both charts; the axes and the read-out carry the ratios' units.
#include "ui/plots/plot_panel.h"

#include "four_bar_curves.h"
#include "plotted_points.h"

#include "ui/plots/hover_readout.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include "kinematics/analysis/quick_return.h"
#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QScatterSeries>
#include <QValueAxis>

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::ui;
using linkwright::ui::test::plotted;
namespace k = linkwright::kinematics;

namespace {

const PlotQuantity kFourBarRatio = PlotQuantity::ofRatio(RatioQuantity::VelocityRatio, k::RatioBodies{2, 4, false});
const PlotQuantity kFourBarAdvantage = PlotQuantity::ofRatio(RatioQuantity::Advantage, k::RatioBodies{2, 4, false});
const PlotQuantity kSliderRatio = PlotQuantity::ofRatio(RatioQuantity::VelocityRatio, k::RatioBodies{2, 4, true});
const PlotQuantity kSliderAdvantage = PlotQuantity::ofRatio(RatioQuantity::Advantage, k::RatioBodies{2, 4, true});

void showRatios(PlotPanel& panel, PlotQuantity ratio, PlotQuantity advantage) {
  REQUIRE(panel.selector()->checkBox(ratio) != nullptr);
  panel.selector()->checkBox(ratio)->setChecked(true);
  panel.selector()->checkBox(advantage)->setChecked(true);
}

// The sample of the sweep a plotted point stands for (x is the crank angle in degrees).
std::size_t sampleAt(const k::SweepResult& s, double xDeg) {
  std::size_t best = 0;
  for (std::size_t j = 1; j < s.size(); ++j)
    if (std::abs(k::radToDeg(s.inputAngle[j]) - xDeg) < std::abs(k::radToDeg(s.inputAngle[best]) - xDeg)) best = j;
  return best;
}

bool closeRelative(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
}

}  // namespace

TEST_CASE("the ratios are offered for four-bars and slider-cranks, unticked at first", "[plot_panel][ratios]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  REQUIRE(panel.curve(kFourBarRatio) != nullptr);
  CHECK(panel.curve(kFourBarRatio)->name == QStringLiteral("ratio ω4/ω2"));
  CHECK(panel.curve(kFourBarAdvantage)->name == QStringLiteral("advantage T4/T2"));
  CHECK_FALSE(panel.selection().contains(kFourBarRatio));
  CHECK(panel.chartView(QuantityKind::VelocityRatio)->isHidden());
  CHECK(panel.chartView(QuantityKind::Advantage)->isHidden());

  doc.reset(*k::designForExample("ls3-engine"));
  CHECK(panel.curve(kSliderRatio) != nullptr);
  CHECK(panel.curve(kFourBarRatio) == nullptr);
  // A Watt II's output is its second rocker, body 6; a shaper's its ram.
  doc.reset(*k::designForExample("watt-ii"));
  const PlotQuantity wattRatio = PlotQuantity::ofRatio(RatioQuantity::VelocityRatio, k::RatioBodies{2, 6, false});
  REQUIRE(panel.curve(wattRatio) != nullptr);
  CHECK(panel.curve(wattRatio)->name == QStringLiteral("ratio ω6/ω2"));
  CHECK(panel.curve(kFourBarRatio) == nullptr);
  doc.reset(*k::designForExample("shaper"));
  const PlotQuantity ramAdvantage = PlotQuantity::ofRatio(RatioQuantity::Advantage, k::RatioBodies{2, 6, true});
  REQUIRE(panel.curve(ramAdvantage) != nullptr);
  CHECK(panel.curve(ramAdvantage)->name == QStringLiteral("advantage F/T2"));
  CHECK(valueAxisTitle(ramAdvantage, AngleUnit::Degrees, QStringLiteral("mm")) == QStringLiteral("F/T2 [1/mm]"));
  doc.reset(*k::designForExample("excavator-boom"));  // a cylinder drives it: no crank, no ratios
  CHECK(panel.curve(ramAdvantage) == nullptr);
  CHECK(panel.curve(wattRatio) == nullptr);
}

TEST_CASE("a four-bar's plotted velocity ratio is the solver's ω4/ω2, its advantage the inverse",
          "[plot_panel][ratios]") {
  for (const char* example : {"thesis-crank-rocker", "alvi-fourbar"}) {
    CAPTURE(example);
    MechanismDocument doc;
    doc.reset(*k::designForExample(example));
    PlotPanel panel(&doc);
    showRatios(panel, kFourBarRatio, kFourBarAdvantage);
    CHECK_FALSE(panel.chartView(QuantityKind::VelocityRatio)->isHidden());
    CHECK_FALSE(panel.chartView(QuantityKind::Advantage)->isHidden());
    const k::SweepResult& s = doc.sweep();
    const std::size_t crank = k::fourbar::kCrank.index, rocker = k::fourbar::kRocker.index;
    const QList<QPointF> ratio = plotted(panel, kFourBarRatio);
    REQUIRE(ratio.size() > 100);
    for (const QPointF& p : ratio) {
      const std::size_t j = sampleAt(s, p.x());
      REQUIRE(s.ok(j));
      CAPTURE(j);
      // Two independent exact routes: Kennedy's I24, and the velocity loop's ω4 over ω2.
      CHECK(closeRelative(p.y(), s.linkOmega[rocker][j] / s.linkOmega[crank][j], 1e-9));
    }
    const QList<QPointF> advantage = plotted(panel, kFourBarAdvantage);
    REQUIRE(advantage.size() > 100);
    for (const QPointF& p : advantage) {
      const std::size_t j = sampleAt(s, p.x());
      CHECK(closeRelative(p.y() * s.linkOmega[rocker][j] / s.linkOmega[crank][j], 1.0, 1e-9));
    }
    CHECK(panel.chartView(QuantityKind::VelocityRatio)->yAxis()->titleText() == QStringLiteral("ω4/ω2"));
    CHECK(panel.chartView(QuantityKind::Advantage)->yAxis()->titleText() == QStringLiteral("T4/T2"));
  }
}

TEST_CASE("the advantage breaks at each rocker limit, which both ratio charts mark", "[plot_panel][ratios]") {
  MechanismDocument doc;  // the thesis crank-rocker: two limits in a turn
  PlotPanel panel(&doc);
  showRatios(panel, kFourBarRatio, kFourBarAdvantage);
  const QList<double> limits = panel.limitMarkers()->lineXs();
  REQUIRE(limits.size() == 2);
  CHECK(panel.advantageLimitMarkers()->lineXs() == limits);
  CHECK(panel.velocityRatioLimitMarkers()->lineXs() == limits);
  // The velocity ratio is zero there: its labelled points sit on the x axis, and its curve
  // changes sign across each limit.
  const QList<QPointF> zeros = panel.velocityRatioLimitMarkers()->points()->points();
  REQUIRE(zeros.size() == 2);
  const QList<QPointF> ratio = plotted(panel, kFourBarRatio);
  for (const QPointF& z : zeros) {
    CHECK(z.y() == 0.0);
    const auto after = std::find_if(ratio.begin(), ratio.end(), [&](const QPointF& p) { return p.x() > z.x(); });
    REQUIRE(after != ratio.begin());
    REQUIRE(after != ratio.end());
    CHECK(std::signbit(std::prev(after)->y()) != std::signbit(after->y()));
  }
  // The advantage runs to ±∞ at each limit: its line is cut there, every piece of one sign.
  const QList<QList<QPointF>> pieces = panel.chartView(QuantityKind::Advantage)->curveItem(kFourBarAdvantage)->runs();
  CHECK(pieces.size() == 3);  // before the first limit, between them, after the second
  for (const QList<QPointF>& points : pieces) {
    REQUIRE_FALSE(points.isEmpty());
    const bool negative = std::signbit(points.front().y());
    for (const QPointF& p : points) CHECK(std::signbit(p.y()) == negative);
    for (const double limit : limits) CHECK_FALSE((points.front().x() < limit && points.back().x() > limit));
  }
  // The value axis is not stretched by the spikes next to the limits.
  // (On a chart tall enough to label its ticks finely, as in the window.)
  panel.resize(900, 2400);
  panel.show();
  QCoreApplication::processEvents();
  panel.settleValueRanges();
  const QValueAxis* axis = panel.chartView(QuantityKind::Advantage)->yAxis();
  double steepest = 0.0;
  for (const QPointF& p : plotted(panel, kFourBarAdvantage)) steepest = std::max(steepest, std::abs(p.y()));
  CHECK(steepest > 100.0);                   // the spikes next to the limits…
  CHECK(axis->max() - axis->min() <= 20.0);  // …run off a chart scaled for the bulk (within ±3)
}

TEST_CASE("a slider-crank's ratios are v/ω2 and F/T2, in its length unit", "[plot_panel][ratios]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("ls3-engine"));
  PlotPanel panel(&doc);
  showRatios(panel, kSliderRatio, kSliderAdvantage);
  const k::SweepResult& s = doc.sweep();
  const std::size_t slider = 2, crank = 0;  // C, the piston pin on a guide along x
  const QList<QPointF> ratio = plotted(panel, kSliderRatio);
  REQUIRE(ratio.size() > 100);
  // v is along the guide's direction, +x or −x: one sign for the whole turn.
  const std::size_t j0 = sampleAt(s, ratio[40].x());
  const double along = std::copysign(1.0, ratio[40].y() * s.velocity[slider][j0].x() / s.linkOmega[crank][j0]);
  for (const QPointF& p : ratio) {
    const std::size_t j = sampleAt(s, p.x());
    CHECK(closeRelative(p.y(), along * s.velocity[slider][j].x() / s.linkOmega[crank][j], 1e-9));
  }
  for (const QPointF& p : plotted(panel, kSliderAdvantage)) {
    const std::size_t j = sampleAt(s, p.x());
    CHECK(closeRelative(p.y() * along * s.velocity[slider][j].x() / s.linkOmega[crank][j], 1.0, 1e-9));
  }
  // Dead centres, 0° and 180° (and 360°): the piston is at rest, the advantage breaks there,
  // and both ratio charts mark them, the rest labelled on the velocity ratio's zero.
  CHECK(panel.chartView(QuantityKind::Advantage)->curveItem(kSliderAdvantage)->runs().size() >= 2);
  CHECK(panel.advantageLimitMarkers()->lineXs() == QList<double>{0.0, 180.0, 360.0});
  CHECK(panel.velocityRatioLimitMarkers()->lineXs() == QList<double>{0.0, 180.0, 360.0});
  CHECK(panel.velocityRatioLimitMarkers()->points()->name() == QStringLiteral("output at rest"));
  CHECK(panel.limitMarkers()->lineXs().isEmpty());  // the angle chart's limits are a rocker's
  CHECK(panel.chartView(QuantityKind::VelocityRatio)->yAxis()->titleText() == QStringLiteral("v/ω2 [mm/rad]"));
  CHECK(panel.chartView(QuantityKind::Advantage)->yAxis()->titleText() == QStringLiteral("F/T2 [1/mm]"));
  // The read-out gives the ratio's own unit whatever the plots' angle unit.
  CHECK(readoutText(*panel.curve(kSliderAdvantage), {90.0, 0.025}, AngleUnit::Degrees, QStringLiteral("mm")) ==
        QStringLiteral("advantage F/T2 = 0.0250 1/mm at crank 90.0°"));
}

TEST_CASE("a shaper's ram rests where its velocity ratio passes through zero, marked on both charts",
          "[plot_panel][ratios]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("shaper"));
  PlotPanel panel(&doc);
  const PlotQuantity ratio = PlotQuantity::ofRatio(RatioQuantity::VelocityRatio, k::RatioBodies{2, 6, true});
  const PlotQuantity advantage = PlotQuantity::ofRatio(RatioQuantity::Advantage, k::RatioBodies{2, 6, true});
  showRatios(panel, ratio, advantage);
  const auto quick = k::shaperQuickReturn(k::asQuickReturn(doc.mechanism())->geometry);
  REQUIRE(quick);
  const QList<double> xs = panel.velocityRatioLimitMarkers()->lineXs();
  REQUIRE(xs.size() == 2);
  CHECK(xs[0] == Approx(k::radToDeg(quick->firstLimitCrankAngle)).margin(0.05));  // read off a 0.5° grid
  CHECK(xs[1] == Approx(k::radToDeg(quick->secondLimitCrankAngle)).margin(0.05));
  CHECK(panel.advantageLimitMarkers()->lineXs() == xs);
}

TEST_CASE("a four-bar's ratio reads out with no unit", "[hover_readout][ratios]") {
  CHECK(readoutText(test::fourBarCurve(kFourBarRatio), {90.0, -0.5}, AngleUnit::Degrees) ==
        QStringLiteral("ratio ω4/ω2 = -0.500 at crank 90.0°"));
}

TEST_CASE("the plot keys of --plots select exactly their curves, and an unknown key is named",
          "[plot_panel][ratios][options]") {
  const auto& curves = test::fourBarCurves();
  QString unknown;
  const auto selection = selectionOfKeys(curves, {"rocker_angle", "mechanical_advantage"}, unknown);
  REQUIRE(selection);
  for (const PlotCurve& c : curves) {
    CAPTURE(c.key.toStdString());
    CHECK(selection->contains(c.quantity) == (c.key == "rocker_angle" || c.key == "mechanical_advantage"));
  }
  CHECK_FALSE(selectionOfKeys(curves, {"rocker_angle", "C_x"}, unknown));
  CHECK(unknown == QStringLiteral("C_x"));  // a four-bar has no slider
}

TEST_CASE("extreme four-bars plot finite ratios or none, never NaN or infinity", "[plot_panel][ratios][errors]") {
  int plottedDesigns = 0;
  for (const k::FourBarLengths& lengths :
       {k::FourBarLengths{1e-6, 1e9, 1e9, 1e9}, k::FourBarLengths{1e3, 1e-3, 1e3, 1e3},
        k::FourBarLengths{50.0, 20.0, 50.0, 20.0} /* a parallelogram: a change point */}) {
    CAPTURE(lengths.frame, lengths.crank, lengths.coupler, lengths.rocker);
    MechanismDocument doc;
    const auto design = k::fourBarDesign(lengths, k::Branch::Open, "mm");
    if (!design) continue;  // refused by the core: nothing to plot
    ++plottedDesigns;
    doc.reset(*design);
    PlotPanel panel(&doc);
    showRatios(panel, kFourBarRatio, kFourBarAdvantage);
    for (const PlotQuantity q : {kFourBarRatio, kFourBarAdvantage})
      for (const QPointF& p : plotted(panel, q)) CHECK((std::isfinite(p.x()) && std::isfinite(p.y())));
    for (const auto kind : {QuantityKind::VelocityRatio, QuantityKind::Advantage}) {
      const QValueAxis* axis = panel.chartView(kind)->yAxis();
      CHECK((std::isfinite(axis->min()) && std::isfinite(axis->max())));
    }
  }
  CHECK(plottedDesigns == 3);  // the core accepts all three: the loop is not empty
}
