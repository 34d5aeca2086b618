#include "ui/plots/plot_panel.h"

#include "ui/plots/axis_range.h"
#include "ui/plots/chart_colors.h"
#include "ui/plots/chart_scale.h"
#include "ui/plots/crank_angle_chart.h"
#include "ui/plots/hover_readout.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/plot_area_alignment.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/plots/quality_bar.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include "kinematics/analysis/advantage_sweep.h"

#include <QChart>
#include <QGraphicsLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <utility>

namespace linkwright::ui {
namespace {

constexpr std::array<QuantityKind, kQuantityKindCount> kKinds{
    QuantityKind::Angle,    QuantityKind::Omega,        QuantityKind::Alpha,         QuantityKind::Position,
    QuantityKind::Velocity, QuantityKind::Acceleration, QuantityKind::VelocityRatio, QuantityKind::Advantage};

// Shares of the panel's height: the chart that names the x axis when presenting gets a little
// more, for that title's line.
constexpr int kChartStretch = 6;
constexpr int kChartMinimumHeight = 110;  // px: six charts (a slider-crank) fit a 768 px screen
constexpr int kTitledChartStretch = 7;

QString titleOf(QuantityKind kind) {
  switch (kind) {
  case QuantityKind::Angle: return PlotPanel::tr("Link angles");
  case QuantityKind::Omega: return PlotPanel::tr("Angular velocities");
  case QuantityKind::Alpha: return PlotPanel::tr("Angular accelerations");
  case QuantityKind::Position: return PlotPanel::tr("Slider positions");
  case QuantityKind::Velocity: return PlotPanel::tr("Slider velocities");
  case QuantityKind::Acceleration: return PlotPanel::tr("Slider accelerations");
  case QuantityKind::VelocityRatio: return PlotPanel::tr("Velocity ratio");
  case QuantityKind::Advantage: return PlotPanel::tr("Mechanical advantage");
  }
  return {};
}

}  // namespace

PlotPanel::PlotPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_quality(new QualityBar(document, this)),
      m_selector(new QuantitySelector(this)), m_limitNote(new QLabel(this)), m_readout(new HoverReadout(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(m_quality);
  layout->addWidget(m_selector);
  // A window drag resizes the charts on every pixel; the sweep follows once it settles.
  m_widthTimer.setSingleShot(true);
  m_widthTimer.setInterval(kResizeSettleMs);
  connect(&m_widthTimer, &QTimer::timeout, this, &PlotPanel::reportPlotWidth);
  m_settleTimer.setSingleShot(true);
  m_settleTimer.setInterval(kDataSettleMs);
  connect(&m_settleTimer, &QTimer::timeout, this, &PlotPanel::settleValueRanges);
  for (const QuantityKind kind : kKinds) {
    auto* view = new QuantityChartView(kind, titleOf(kind), this);
    // Small enough that six charts (a slider-crank) fit the window's height; taller where the
    // legend needs it (alignCharts).
    view->setMinimumHeight(kChartMinimumHeight);
    connect(view, &QuantityChartView::curveHovered, this, [this](PlotQuantity q, QPointF p, bool inside) {
      if (const PlotCurve* c = curve(q))
        m_readout->showPoint(*c, p, m_unit, QString::fromStdString(m_document->lengthUnit()), inside, m_x);
    });
    connect(view, &QuantityChartView::overlayHovered, m_readout, &HoverReadout::showText);
    // One layout pass resizes the views one after another: each lays out only itself again,
    // the others keep their layouts, so aligning after every resize does not grow as n².
    connect(view, &QuantityChartView::resized, this, [this, view] { alignCharts({view}); });
    m_views[static_cast<std::size_t>(kind)] = view;
    layout->addWidget(view, kChartStretch);
  }
  m_limitNote->setObjectName(QStringLiteral("limit_note"));
  m_limitNote->setWordWrap(true);
  m_limitNote->hide();
  layout->addWidget(m_limitNote);
  layout->addWidget(m_readout);
  QuantityChartView* angles = chartView(QuantityKind::Angle);
  m_limits = std::make_unique<LimitMarkers>(angles->chart(), angles->xAxis(), angles->yAxis());
  QuantityChartView* ratio = chartView(QuantityKind::VelocityRatio);
  m_ratioLimits = std::make_unique<LimitMarkers>(ratio->chart(), ratio->xAxis(), ratio->yAxis());
  QuantityChartView* advantage = chartView(QuantityKind::Advantage);
  m_advantageLimits = std::make_unique<LimitMarkers>(advantage->chart(), advantage->xAxis(), advantage->yAxis());

  connect(m_selector, &QuantitySelector::selectionChanged, this, &PlotPanel::onSelectionChanged);
  connect(m_document, &MechanismDocument::changed, this, &PlotPanel::onDocumentChanged);
  // A new mechanism is swept once, for what these plots will show of it.
  m_document->setRequestSource(this, [this](const kinematics::Mechanism& m, const kinematics::Pose& pose) {
    const std::vector<PlotCurve> curves = plotCurves(m, pose);
    return requestFor(selectionAfter(m_curves, selection(), curves), curves);
  });
  refreshCurves();
  // Ask for exactly what the default selection shows, and plot it.
  applySelection();
}

// m_limits goes before the QWidget base deletes the charts, and touches none of them.
PlotPanel::~PlotPanel() = default;

void PlotPanel::setAngleUnit(AngleUnit unit) {
  if (unit == m_unit) return;
  m_unit = unit;
  m_readout->clearPoint();
  m_overlayStale = true;  // placed anew in the new unit
  refreshData();
}

void PlotPanel::setComparison(const kinematics::compare::Comparison& comparison, const QString& source) {
  m_comparison = comparison;
  m_comparisonSource = source;
  m_overlayStale = true;
  refreshData();
}

void PlotPanel::clearComparison() {
  if (!m_comparison) return;
  m_comparison.reset();
  m_overlayStale = true;
  refreshData();
}

QList<QChartView*> PlotPanel::chartViews() const {
  QList<QChartView*> views;
  for (QuantityChartView* view : m_views) views.append(view);
  return views;
}

QList<QGraphicsView*> PlotPanel::graphicsViews() const {
  QList<QGraphicsView*> views;
  for (QuantityChartView* view : m_views) views.append(view);
  return views;
}

QString PlotPanel::chartTitle(int index) const {
  if (index < 0 || index >= kQuantityKindCount) return {};
  return titleOf(kKinds[static_cast<std::size_t>(index)]);
}

QuantitySelection PlotPanel::selection() const { return m_selector->selection(); }

void PlotPanel::setSelection(const QuantitySelection& selection) { m_selector->setSelection(selection); }

QuantityChartView* PlotPanel::chartView(QuantityKind kind) const { return m_views[static_cast<std::size_t>(kind)]; }

void PlotPanel::onDocumentChanged(Changes what) {
  // A new structure has new quantities; the document has already swept for what they need
  // (setRequestSource), so the plots only follow.
  const bool newCurves = (what & Change::Design) && refreshCurves();
  if (what & Change::PlotAxis) m_readout->clearPoint();
  // A drag's sweep still in a worker changes nothing plotted yet: its landing (Request) does.
  const bool swept = (what & Change::Design) && !m_document->sweepPending();
  if (newCurves || swept || (what & (Changes(Change::Request) | Change::PlotAxis))) refreshData();
  else if (what & (Changes(Change::Motion) | Change::Design)) refreshCursor();
}

void PlotPanel::setOnScreen(bool onScreen) {
  if (onScreen == m_onScreen) return;
  m_onScreen = onScreen;
  if (onScreen && m_stale) {
    m_stale = false;
    refreshData();
  }
  // Laid out while hidden (a new font in presentation mode), a chart's legend may need more
  // height than it was given; a view that grows is aligned again as it resizes.
  if (onScreen) fitLegends();
}

void PlotPanel::fitLegends() {
  // A fitted height only grows until the legends' entries or fonts change (m_legendsRefit): a
  // taller chart can bring up the page's scroll bar, which narrows the charts, and a height
  // that followed that back down brought the bar and the chart into a loop without end.
  const bool afresh = std::exchange(m_legendsRefit, false);
  for (QuantityChartView* view : m_views) {
    if (view->isHidden()) continue;
    view->chart()->layout()->activate();  // the legend as the next paint lays it out
    view->setMinimumHeight(legendFittingHeight(view, afresh ? kChartMinimumHeight : view->minimumHeight()));
  }
}

void PlotPanel::onSelectionChanged() {
  applySelection();
  emit selectionChanged();
}

bool PlotPanel::refreshCurves() {
  std::vector<PlotCurve> curves = plotCurves(m_document->mechanism(), m_document->pose());
  if (curves == m_curves && !m_curves.empty()) return false;
  // Another kind of linkage starts from its own defaults; renamed links keep the user's ticks.
  const QuantitySelection selection = selectionAfter(m_curves, m_selector->selection(), curves);
  m_curves = std::move(curves);
  m_overlayStale = true;  // the compared columns' curves may have new names or be gone
  m_selector->setCurves(m_curves, selection);
  for (QuantityChartView* view : m_views) view->setCurves(m_curves);
  m_legendsRefit = true;
  if (m_limits) m_limits->raise();  // last in the angle chart's legend, as "rocker limit" reads best
  if (m_ratioLimits) m_ratioLimits->raise();
  m_readout->clearPoint();
  return true;
}

double PlotPanel::plotAreaWidth() const {
  for (QuantityChartView* view : m_views) {
    if (view->isHidden()) continue;
    view->chart()->layout()->activate();  // margins set by alignCharts take effect here
    return view->chart()->plotArea().width();
  }
  return 0.0;
}

void PlotPanel::reportPlotWidth() {
  m_widthTimer.stop();
  // Hidden charts are not laid out, so their plot area says nothing about the screen.
  if (!isVisible()) return;
  if (const double width = plotAreaWidth(); width > 0.0) m_document->setDisplayWidth(std::round(width));
}

void PlotPanel::applySelection() {
  m_legendsRefit = true;  // curves shown or hidden: other legend entries
  kinematics::SolveRequest wanted = requestFor(selection(), m_curves);
  wanted.newton = m_document->request().newton;  // the quality's, not the selection's
  // A new request re-sweeps and comes back as Change::Request, which re-plots; otherwise
  // only the visibility changed and the current sweep serves.
  if (wanted != m_document->request()) m_document->setRequest(wanted);
  else refreshData();
}

void PlotPanel::refreshData() {
  if (!m_onScreen) {
    m_stale = true;
    return;
  }
  const kinematics::Design& design = m_document->design();
  const QString lengthUnit = QString::fromStdString(m_document->lengthUnit());
  const kinematics::SweepResult& sweep = m_document->sweep();
  const QuantitySelection shown = selection();
  const PlotXAxis before = m_x;
  m_x = plotXAxis(design, sweep, m_document->plotAxis(), m_unit);
  const PlotXAxis& x = m_x;
  // The rows stay where they are while a drag changes the curves: placed anew only when the
  // x axis or the units change.
  if (m_overlayStale || x.source != before.source || x.range != before.range) {
    m_overlay = m_comparison ? overlayCurves(*m_comparison, m_comparisonSource, m_curves, x, m_unit)
                             : std::vector<OverlayCurve>{};
    m_overlayStale = false;
  }
  // The document derives the ratios from the sweep, asked only while a ratio is shown.
  const bool ratiosShown =
      shown.any(QuantityKind::VelocityRatio, m_curves) || shown.any(QuantityKind::Advantage, m_curves);
  const kinematics::AdvantageSeries* ratios = ratiosShown && m_document->ratios() ? &*m_document->ratios() : nullptr;
  QList<QuantityChartView*> changed;  // their axes or legends: laid out again
  // Data that came before the last ones settled are a drag's, or an animation's.
  const DataFlow flow = m_settleTimer.isActive() ? DataFlow::Changing : DataFlow::Settled;
  for (QuantityChartView* view : m_views) {
    const bool visible = shown.any(view->kind(), m_curves);
    const bool appears = visible == view->isHidden();
    view->setVisible(visible);
    view->setOverlay(m_overlay);
    if (view->setData(sweep, shown, m_unit, x, lengthUnit, ratios, flow) || appears) changed.append(view);
  }
  for (QuantityChartView* view : showXTitles())
    if (!changed.contains(view)) changed.append(view);
  const QString note = placeLimitMarkers(shown, ratios, changed);
  QuantityChartView* angles = chartView(QuantityKind::Angle);
  m_limitNote->setText(note);
  m_limitNote->setVisible(!note.isEmpty() && !angles->isHidden());
  refreshCursor();
  if (!changed.isEmpty()) alignCharts(changed);  // axis labels or legends may have changed width
  m_settleTimer.start();
}

QString PlotPanel::placeLimitMarkers(const QuantitySelection& shown, const kinematics::AdvantageSeries* ratios,
                                     QList<QuantityChartView*>& changed) {
  const kinematics::Design& design = m_document->design();
  const kinematics::SweepResult& sweep = m_document->sweep();
  // Limit positions are a four-bar's (empty otherwise), on its rocker's curve; on a time base
  // wherever the law passes them, unless that is too often to read.
  const kinematics::LimitReport& limits = m_document->analysis().limits;
  QList<QPointF> points;
  QString note;
  if (!design.time) {
    points = limitMarkerPoints(limits, sweep, design.fromDeg, design.toDeg, m_unit);
  } else if (auto inTime = limitMarkerPointsInTime(limits, sweep, *design.time, m_x.source.axis, m_unit)) {
    points = *inTime;
  } else {
    note = tr("Rocker limit positions are not marked: the crank passes them more than %1 times in this time span.")
               .arg(kMostLimitMarkers);
  }
  const bool fourBar = m_document->fourBar().has_value();
  const auto place = [&](LimitMarkers& markers, QuantityKind kind, const QList<QPointF>& at, bool labelled) {
    QuantityChartView* view = chartView(kind);
    markers.setYSpan(view->valueRange().min, view->valueRange().max);
    if (markers.setPositions(at, labelled) && !changed.contains(view)) changed.append(view);
  };
  place(*m_limits, QuantityKind::Angle, points, fourBar && shown.contains(PlotQuantity::RockerAngle));
  // At a limit the rocker is at rest: the velocity ratio is zero (labelled on its curve) and
  // the advantage infinite (the line its two branches run up against). Another linkage's
  // output (a slider, a ram, a six-bar's last rocker) rests where its ratio series passes
  // through zero.
  QList<QPointF> onZero = points;
  if (!fourBar && ratios != nullptr) {
    onZero.clear();
    for (const kinematics::OutputRest& rest : kinematics::outputRests(*ratios)) {
      const double x0 = sampleX(sweep, rest.sample, m_x.source, m_unit);
      const double x1 = rest.fraction > 0.0 ? sampleX(sweep, rest.sample + 1, m_x.source, m_unit) : x0;
      onZero.append(QPointF(x0 + rest.fraction * (x1 - x0), 0.0));
    }
  }
  for (QPointF& p : onZero) p.setY(0.0);
  m_ratioLimits->setName(fourBar ? tr("rocker limit") : tr("output at rest"));
  place(*m_ratioLimits, QuantityKind::VelocityRatio, onZero, true);
  place(*m_advantageLimits, QuantityKind::Advantage, onZero, false);
  return note;
}

void PlotPanel::settleValueRanges() {
  m_settleTimer.stop();
  QList<QuantityChartView*> changed;
  for (QuantityChartView* view : m_views)
    if (view->settleValueRange()) changed.append(view);
  if (changed.isEmpty()) return;
  const auto span = [this](LimitMarkers& markers, QuantityKind kind) {
    const AxisRange& range = chartView(kind)->valueRange();
    markers.setYSpan(range.min, range.max);
  };
  span(*m_limits, QuantityKind::Angle);
  span(*m_ratioLimits, QuantityKind::VelocityRatio);
  span(*m_advantageLimits, QuantityKind::Advantage);
  alignCharts(changed);
}

void PlotPanel::setPresentationScale(double factor) {
  m_legendsRefit = true;
  for (QuantityChartView* view : m_views) setChartScale(view->chart(), factor);
  // In front of a class the controls give their height to the charts: at the larger text the
  // charts' axis titles would not fit beside short plots.
  m_presenting = factor > 1.0;
  m_quality->setVisible(!m_presenting);
  m_selector->setVisible(!m_presenting);
  m_readout->setVisible(!m_presenting);  // its hint line too: a hover shows the value's tooltip
  showXTitles();
  alignCharts();  // the axis labels' widths changed
}

QList<QuantityChartView*> PlotPanel::showXTitles() {
  // The charts share one x axis: in front of a class only the bottom one names it, and the
  // height the others save goes to their plots, so the larger value-axis titles fit beside them.
  QuantityChartView* bottom = nullptr;
  for (QuantityChartView* view : m_views)
    if (!view->isHidden()) bottom = view;
  QList<QuantityChartView*> changed;
  auto* box = static_cast<QVBoxLayout*>(layout());
  for (QuantityChartView* view : m_views) {
    const bool shown = !m_presenting || view == bottom;
    // The bottom chart is that title taller, so its plot is as high as the others'.
    // Set only when it differs: QBoxLayout re-lays out the window on every call.
    const int stretch = shown && m_presenting ? kTitledChartStretch : kChartStretch;
    if (box->stretch(box->indexOf(view)) != stretch) box->setStretchFactor(view, stretch);
    PlotAxesItem* axes = plotAxes(view->chart());
    if (axes->titleShown(Qt::Horizontal) == shown) continue;
    axes->setTitleShown(Qt::Horizontal, shown);
    changed.append(view);
  }
  return changed;
}

void PlotPanel::refreshColors() {
  for (QuantityChartView* view : m_views) applyChartColors(view->chart());
  refreshCurves();  // the curves are the links' colours: new series in the new ones
  refreshData();
}

QString PlotPanel::limitNote() const { return m_limitNote->isHidden() ? QString() : m_limitNote->text(); }

void PlotPanel::alignCharts() { alignCharts({m_views.begin(), m_views.end()}); }

void PlotPanel::alignCharts(const QList<QuantityChartView*>& changed) {
  QList<QChart*> shown;
  QList<QChart*> relaid;
  for (QuantityChartView* view : m_views) {
    if (view->isHidden()) continue;
    shown.append(view->chart());
    if (changed.contains(view)) relaid.append(view->chart());
  }
  alignPlotAreas(shown, relaid);
  fitLegends();
  // A resize, or new axis labels or legend entries, may have changed the plot area's width.
  if (!shown.isEmpty()) m_widthTimer.start();
}

void PlotPanel::refreshCursor() {
  if (!m_onScreen) {
    m_stale = true;
    return;
  }
  const std::optional<double> x = cursorX(*m_document, m_x, m_unit);
  for (QuantityChartView* view : m_views) view->setCursorX(x);
}

}  // namespace linkwright::ui
