#include "ui/plots/quantity_chart_view.h"

#include "ui/colors.h"
#include "ui/plots/chart_scale.h"
#include "ui/plots/chart_view_setup.h"
#include "ui/plots/crank_angle_chart.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/series_visibility.h"

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace linkwright::ui {

QuantityChartView::QuantityChartView(QuantityKind kind, const QString& title, QWidget* parent)
    : QChartView(parent), m_kind(kind), m_xAxis(new QValueAxis), m_yAxis(new QValueAxis) {
  QChart* chart = makeCrankAngleChart(title, m_xAxis, m_yAxis);
  setChart(chart);  // the view owns the chart, the chart its axes and series
  setUpChartView(this);
  // OpenGL stays off (the default): a few 721-point lines draw well under a frame in
  // software, and the OpenGL path cannot be exported as SVG.
  m_cursor = makeCrankCursor(chart, m_xAxis, m_yAxis);
  // A shorter plot labels fewer ticks; the data stay as they are. (A new range changes the
  // labels' width, not the plot's height, so this settles at once.)
  // A new plot area also changes the curves' scale: they are drawn again if it matters.
  connect(chart, &QChart::plotAreaChanged, this, [this] {
    applyTickStep(m_xAxis, m_xRange, this->chart()->plotArea().width());
    fitLegendNames();
    if (tickBudget() != m_tickBudget) applyValueRange();
    else
      for (Curve& curve : m_curves) curve.line.rescale();
  });
}

QuantityChartView::~QuantityChartView() = default;

void QuantityChartView::setCurves(const std::vector<PlotCurve>& curves) {
  std::vector<PlotCurve> mine;
  for (const PlotCurve& c : curves)
    if (quantityKind(c.quantity) == m_kind) mine.push_back(c);
  const bool same =
      mine.size() == m_curves.size() && std::equal(mine.begin(), mine.end(), m_curves.begin(),
                                                   [](const PlotCurve& a, const Curve& b) { return a == b.curve; });
  if (same) return;
  for (Curve& curve : m_curves) curve.line.removeFromChart();
  m_curves.clear();
  removeMarkers();  // outlined in the curves' colours (a theme switch): the next setOverlay remakes them
  m_curves.reserve(mine.size());
  for (const PlotCurve& c : mine) {
    m_curves.push_back({c, SegmentedLine(chart(), m_xAxis, m_yAxis, {c.key, c.name, c.color})});
    const PlotQuantity q = c.quantity;
    connect(m_curves.back().line.item(), &CurveItem::hovered, this,
            [this, q](qsizetype run, QPointF p, bool inside) { onCurveHovered(q, run, p, inside); });
  }
  m_cursor->raise();  // over the curves, as before they were replaced
}

bool QuantityChartView::setData(const kinematics::SweepResult& sweep, const QuantitySelection& selection,
                                AngleUnit unit, const PlotXAxis& x, const QString& lengthUnit,
                                const kinematics::AdvantageSeries* ratios, DataFlow flow) {
  // The axes first: the curves are simplified for the scale they set (segmented_line.h).
  m_values.clear();
  m_runs.resize(m_curves.size());
  for (std::size_t i = 0; i < m_curves.size(); ++i) {
    if (selection.contains(m_curves[i].curve.quantity))
      buildSeriesRuns(sweep, m_curves[i].curve.quantity, unit, m_runs[i], x.source, ratios);
    else m_runs[i].runs.clear();
    for (const QList<QPointF>& run : m_runs[i].runs)
      for (const QPointF& p : run) m_values.push_back(p.y());
  }
  // Another tool's rows are on the value axis too: a wrong column shows how wrong it is.
  for (const Markers& m : m_markers)
    if (selection.contains(m.overlay.quantity))
      for (const QPointF& p : m.overlay.points) m_values.push_back(p.y());
  // Spikes next to a toggle would squash every other value flat: they run off the chart
  // instead, and the hover read-out still gives their value.
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // The advantage runs to ±∞ at every limit, on both sides: its tails are wider, and what a
  // reader wants is the usable band between them.
  const double tail = m_kind == QuantityKind::Advantage ? 0.15 : 0.05;
  std::tie(m_lo, m_hi) = m_values.empty() ? std::pair<double, double>{kNone, -kNone} : robustSpan(m_values, tail);
  const int budget = tickBudget();
  if (budget != m_tickBudget || !keepsRange(m_valueRange, m_lo, m_hi))
    m_valueRange = refittedRange(m_lo, m_hi, flow, budget);
  m_tickBudget = budget;
  applyAxisRange(m_yAxis, m_valueRange);
  m_cursor->setYSpan(m_valueRange.min, m_valueRange.max);
  // A ratio's title depends on the linkage its curves are of.
  const QString title = m_curves.empty() ? valueAxisTitle(m_kind, unit, lengthUnit)
                                         : valueAxisTitle(m_curves.front().curve.quantity, unit, lengthUnit);
  if (m_yAxis->titleText() != title) m_yAxis->setTitleText(title);
  applyAxisRange(m_xAxis, x.range);
  m_xRange = x.range;
  applyTickStep(m_xAxis, x.range, chart()->plotArea().width());
  if (m_xAxis->titleText() != x.title) m_xAxis->setTitleText(x.title);
  ChartLayoutInputs inputs{axesRoom(chart()), {}};
  for (std::size_t i = 0; i < m_curves.size(); ++i) {
    const bool shown = selection.contains(m_curves[i].curve.quantity);
    m_curves[i].line.setRuns(m_runs[i], shown);
    inputs.legend.push_back(shown);
  }
  // One legend entry names the table for all its columns on this chart: the markers' outline
  // colour already says which curve each belongs to.
  bool listed = false;
  for (const Markers& m : m_markers) {
    const bool shown = selection.contains(m.overlay.quantity);
    const bool inLegend = shown && !listed;
    listed = listed || inLegend;
    if (shown != m.series->isVisible()) chart()->layout()->invalidate();  // see SegmentedLine::setRuns
    setSeriesShown(chart(), m.series, shown, inLegend);
    inputs.legend.push_back(inLegend);
  }
  fitLegendNames();
  return inputs.replace(m_layoutInputs);
}

// Qt Charts gives a legend on the right at most 0.4 of the chart's width (its layout's rule) and
// elides every entry beyond ("cou…", "rock…" on a projector's 1024 px). Where the curves' whole
// names need more, they go by their symbols (θ3, θ4, μ), which fit, in the link's colour as on the
// canvas; the checkboxes above the charts spell them out. From the whole names' widths, so it
// does not depend on the names shown. (Series renamed later keep the label set here until the
// next fit.)
void QuantityChartView::fitLegendNames() {
  QLegend* legend = chart()->legend();
  if (!legend->isVisible()) return;
  const QFontMetricsF metrics(legend->font());
  double widestShown = 0.0, widestWhole = 0.0;
  for (QLegendMarker* marker : legend->markers()) {
    // Qt's width for the legend counts hidden entries too; an entry is elided by its own width.
    widestShown = std::max(widestShown, metrics.horizontalAdvance(marker->label()));
    if (!marker->isVisible()) continue;
    QString whole = marker->label();
    for (const Curve& c : m_curves)
      if (marker->series() == c.line.legendSeries()) whole = c.curve.name;
    widestWhole = std::max(widestWhole, metrics.horizontalAdvance(whole));
  }
  const double decoration = legend->effectiveSizeHint(Qt::PreferredSize).width() - widestShown;
  const QMarginsF margins = chart()->margins();
  const double room = 0.4 * (chart()->size().width() - margins.left() - margins.right());
  const bool whole = decoration + widestWhole <= room;
  for (Curve& c : m_curves) c.line.setLegendName(whole || c.curve.symbol.isEmpty() ? c.curve.name : c.curve.symbol);
  // The other entries (the rocker's limits, a compared table's rows) by their last word: "limit".
  for (QLegendMarker* marker : legend->markers()) {
    const bool curve = std::any_of(m_curves.begin(), m_curves.end(),
                                   [&](const Curve& c) { return marker->series() == c.line.legendSeries(); });
    if (curve) continue;
    const QString name = marker->series()->name();
    const QString label = whole ? name : name.section(QLatin1Char(' '), -1);
    if (marker->label() != label) marker->setLabel(label);
  }
}

void QuantityChartView::setOverlay(const std::vector<OverlayCurve>& overlay) {
  std::vector<const OverlayCurve*> mine;
  for (const OverlayCurve& o : overlay)
    if (quantityKind(o.quantity) == m_kind) mine.push_back(&o);
  const bool same = mine.size() == m_markers.size() &&
                    std::equal(mine.begin(), mine.end(), m_markers.begin(),
                               [](const OverlayCurve* a, const Markers& b) { return *a == b.overlay; });
  if (same) return;
  removeMarkers();
  for (const OverlayCurve* o : mine) {
    auto* series = new QScatterSeries;
    series->setName(o->name);
    series->setObjectName(QStringLiteral("compared_rows"));
    series->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    series->setMarkerSize(9.0 * chartScale(chart()));
    QColor color = colors().label;
    for (const Curve& curve : m_curves)
      if (curve.curve.quantity == o->quantity) color = curve.curve.color;
    series->setColor(colors().comparedRowFill);
    series->setPen(QPen(color, scaledPenWidth(chart(), 1.5)));
    series->replace(o->points);
    chart()->addSeries(series);
    series->attachAxis(m_xAxis);
    series->attachAxis(m_yAxis);
    for (int i = 0; i < static_cast<int>(o->flagged.size()); ++i)
      if (o->flagged[i]) series->setPointConfiguration(i, QXYSeries::PointConfiguration::Color, colors().flaggedRow);
    setSeriesShown(chart(), series, false, false);  // until setData knows the selection
    const QList<QPointF> points = o->points;
    const QList<QString> texts = o->descriptions;
    connect(series, &QXYSeries::hovered, this, [this, points, texts](const QPointF& p, bool inside) {
      // The marker under the mouse: the row nearest in plot units, x first.
      qsizetype best = -1;
      for (qsizetype i = 0; i < points.size(); ++i)
        if (best < 0 || std::abs(points[i].x() - p.x()) + std::abs(points[i].y() - p.y()) <
                            std::abs(points[best].x() - p.x()) + std::abs(points[best].y() - p.y()))
          best = i;
      if (best >= 0) emit overlayHovered(texts[best], inside);
    });
    m_markers.push_back({*o, series});
  }
  m_cursor->raise();
}

void QuantityChartView::removeMarkers() {
  for (const Markers& m : m_markers) {
    chart()->removeSeries(m.series);
    delete m.series;
  }
  m_markers.clear();
}

QScatterSeries* QuantityChartView::overlaySeries(PlotQuantity quantity) const {
  for (const Markers& m : m_markers)
    if (m.overlay.quantity == quantity) return m.series;
  return nullptr;
}

bool QuantityChartView::settleValueRange() {
  if (niceValueRange(m_lo, m_hi, m_tickBudget) == m_valueRange) return false;
  applyValueRange();
  const QMargins before = std::exchange(m_layoutInputs.axesRoom, axesRoom(chart()));
  return m_layoutInputs.axesRoom != before;
}

int QuantityChartView::tickBudget() const {
  // Labels closer than about one and a half lines of text crowd each other (Qt Charts used to
  // elide them all to "…"). Before the first layout, the default.
  constexpr int kMostTicks = 6;
  const double height = chart()->plotArea().height();
  if (height <= 0.0) return kMostTicks;
  const double spacing = 1.5 * QFontMetricsF(m_yAxis->labelsFont()).height();
  return std::clamp(static_cast<int>(height / spacing), 2, kMostTicks);
}

void QuantityChartView::applyValueRange() {
  m_tickBudget = tickBudget();
  m_valueRange = niceValueRange(m_lo, m_hi, m_tickBudget);
  applyAxisRange(m_yAxis, m_valueRange);
  m_cursor->setYSpan(m_valueRange.min, m_valueRange.max);
  for (Curve& curve : m_curves) curve.line.rescale();
}

void QuantityChartView::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  emit resized();
}

void QuantityChartView::setCursorX(std::optional<double> x) { m_cursor->setX(x); }

CurveItem* QuantityChartView::curveItem(PlotQuantity quantity) const {
  for (const Curve& curve : m_curves)
    if (curve.curve.quantity == quantity) return curve.line.item();
  return nullptr;
}

QList<QPointF> QuantityChartView::samples(PlotQuantity quantity) const {
  for (const Curve& curve : m_curves)
    if (curve.curve.quantity == quantity) return curve.line.samples();
  return {};
}

void QuantityChartView::onCurveHovered(PlotQuantity quantity, qsizetype run, QPointF point, bool inside) {
  for (const Curve& curve : m_curves)
    if (curve.curve.quantity == quantity)
      if (const auto sample = curve.line.nearestSample(run, point.x())) emit curveHovered(quantity, *sample, inside);
}

}  // namespace linkwright::ui
