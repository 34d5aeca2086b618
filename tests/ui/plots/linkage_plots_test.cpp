// Plots for linkages other than four-bars: the quantities come from the mechanism (every
// moving link but the crank, a transmission angle per dyad joint, a slider's stroke), the
// curves hold the sweep's values, and slider charts appear only where there are sliders.
#include "ui/plots/plot_panel.h"

#include "ui/plots/limit_markers.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <functional>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;
using k::ColumnQuantity;

namespace {

QList<QPointF> plotted(const PlotPanel& panel, PlotQuantity q) { return panel.chartView(quantityKind(q))->samples(q); }

QStringList keys(const std::vector<PlotCurve>& curves) {
  QStringList out;
  for (const PlotCurve& c : curves) out << c.key;
  return out;
}

}  // namespace

TEST_CASE("a slider-crank plots its rod and its piston's stroke, velocity and acceleration", "[plot_panel][linkage]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("ls3-engine"));
  PlotPanel panel(&doc);
  CHECK(keys(panel.curves()) == QStringList{"rod_angle", "transmission_angle", "rod_omega", "rod_alpha", "C_x", "C_vx",
                                            "C_ax", "velocity_ratio", "mechanical_advantage"});
  // With a slider, its three charts and the angles show first; the rod's ω and α are a tick away.
  for (const auto kind :
       {QuantityKind::Angle, QuantityKind::Position, QuantityKind::Velocity, QuantityKind::Acceleration})
    CHECK_FALSE(panel.chartView(kind)->isHidden());
  CHECK(panel.chartView(QuantityKind::Omega)->isHidden());
  CHECK(panel.chartView(QuantityKind::Alpha)->isHidden());
  CHECK(panel.chartView(QuantityKind::VelocityRatio)->isHidden());   // the ratios are asked for by name
  CHECK((doc.request().velocities && doc.request().accelerations));  // the piston's acceleration needs them

  const k::SweepResult& s = doc.sweep();
  const PlotQuantity x{ColumnQuantity::PointX, 2}, a{ColumnQuantity::PointAx, 2};
  const QList<QPointF> stroke = plotted(panel, x);
  const QList<QPointF> accel = plotted(panel, a);
  REQUIRE(stroke.size() == static_cast<qsizetype>(s.size()));
  for (std::size_t j : {std::size_t{0}, std::size_t{100}, std::size_t{360}}) {
    const auto i = static_cast<qsizetype>(j);
    CHECK(stroke[i].x() == k::radToDeg(s.inputAngle[j]));
    CHECK(stroke[i].y() == s.position[2][j].x());
    CHECK(accel[i].y() == s.acceleration[2][j].x());
  }
  CHECK(panel.chartView(QuantityKind::Position)->yAxis()->titleText() == QStringLiteral("position [mm]"));
  CHECK(panel.chartView(QuantityKind::Acceleration)->yAxis()->titleText() == QStringLiteral("a [mm/s²]"));

  panel.selector()->checkBox({ColumnQuantity::LinkOmega, 1})->setChecked(true);
  CHECK_FALSE(panel.chartView(QuantityKind::Omega)->isHidden());
  CHECK(plotted(panel, {ColumnQuantity::LinkOmega, 1}).size() == static_cast<qsizetype>(s.size()));
}

TEST_CASE("a six-bar plots links 3 to 6 and both transmission angles, back to a four-bar restores its curves",
          "[plot_panel][linkage]") {
  MechanismDocument doc;
  PlotPanel panel(&doc);
  doc.reset(*k::designForExample("watt-ii"));
  CHECK(keys(panel.curves()) == QStringList{"coupler_angle", "rocker_angle", "link5_angle", "link6_angle",
                                            "transmission_angle_C", "transmission_angle_E", "coupler_omega",
                                            "rocker_omega", "link5_omega", "link6_omega", "coupler_alpha",
                                            "rocker_alpha", "link5_alpha", "link6_alpha", "velocity_ratio",
                                            "mechanical_advantage"});
  CHECK(panel.curve({ColumnQuantity::LinkAngle, 3})->name == QStringLiteral("link5 θ5"));
  CHECK(panel.curve({ColumnQuantity::TransmissionAngle, 6})->name == QStringLiteral("μ at E"));
  for (const auto kind : {QuantityKind::Position, QuantityKind::Velocity, QuantityKind::Acceleration})
    CHECK(panel.chartView(kind)->isHidden());
  const QList<QPointF> link6 = plotted(panel, {ColumnQuantity::LinkAlpha, 4});
  REQUIRE(link6.size() == static_cast<qsizetype>(doc.sweep().size()));
  CHECK(link6[42].y() == k::radToDeg(doc.sweep().linkAlpha[4][42]));
  CHECK(panel.limitMarkers()->lineXs().isEmpty());

  doc.reset(linkwright::testing::fourBar());
  CHECK(keys(panel.curves()).size() == 9);  // its seven and the two ratios
  CHECK(panel.limitMarkers()->lineXs().size() == 2);
  CHECK_FALSE(panel.chartView(QuantityKind::Alpha)->isHidden());
}

TEST_CASE("a short chart labels fewer ticks, so that no labels overlap", "[plot_panel][linkage]") {
  // Qt Charts elided every label of a value axis whose labels would overlap: the shaper's four
  // charts in an 880 px window left its slider charts with "…" for every value.
  MechanismDocument doc;
  doc.reset(*k::designForExample("shaper"));
  PlotPanel panel(&doc);
  panel.show();
  QuantityChartView* view = panel.chartView(QuantityKind::Position);
  for (const int height : {700, 2400}) {
    CAPTURE(height);
    panel.resize(500, height);
    QCoreApplication::processEvents();
    view->chart()->layout()->activate();
    const double area = view->chart()->plotArea().height();
    const double label = QFontMetricsF(view->yAxis()->labelsFont()).height();
    const int ticks = view->yAxis()->tickCount();
    INFO("plot area " << area << " px, label " << label << " px");
    REQUIRE(ticks >= 2);
    CHECK(area / (ticks - 1) >= label);     // room between ticks for each label
    if (height == 2400) CHECK(ticks >= 5);  // a tall chart keeps a fine scale
  }
}

// Qt Charts gives a legend on the right at most 0.4 of the chart's width and elides what is
// wider: on a projector's 1024 px the Watt II's entries read "co…", "ro…", "lin…". A narrow
// chart names its curves by their symbols, which fit; a wide one by their whole names.
TEST_CASE("a narrow chart's legend names its curves by their symbols, whole", "[plot_panel][linkage]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("watt-ii"));
  PlotPanel panel(&doc);
  panel.show();
  QuantityChartView* view = panel.chartView(QuantityKind::Angle);
  for (const int width : {330, 1400}) {
    CAPTURE(width);
    panel.resize(width, 1200);
    QCoreApplication::processEvents();
    view->chart()->layout()->activate();
    QStringList labels;
    for (const QLegendMarker* marker : view->chart()->legend()->markers())
      if (marker->isVisible()) labels << marker->label();
    INFO(labels.join(", ").toStdString());
    if (width == 330) CHECK(labels.mid(0, 6) == QStringList{"θ3", "θ4", "θ5", "θ6", "μ C", "μ E"});
    else CHECK(labels.mid(0, 6) == QStringList{"coupler θ3", "rocker θ4", "link5 θ5", "link6 θ6", "μ at C", "μ at E"});
    // Whole: no text Qt shows in the legend is elided.
    std::function<void(const QGraphicsItem*)> visit = [&](const QGraphicsItem* item) {
      if (const auto* text = dynamic_cast<const QGraphicsTextItem*>(item); text != nullptr && text->isVisible())
        CHECK_FALSE(text->toPlainText().contains(QChar(0x2026)));
      for (const QGraphicsItem* child : item->childItems()) visit(child);
    };
    visit(view->chart()->legend());
  }
}
