#include "ui/plots/plot_panel.h"

#include "ui/plots/axis_range.h"
#include "ui/plots/hover_readout.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/plot_area_alignment.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"

#include <QVBoxLayout>

namespace linkwright::ui {
namespace {

constexpr std::array<QuantityKind, kQuantityKindCount> kKinds{QuantityKind::Angle, QuantityKind::Omega,
                                                              QuantityKind::Alpha};

QString titleOf(QuantityKind kind) {
  switch (kind) {
  case QuantityKind::Angle: return PlotPanel::tr("Link angles");
  case QuantityKind::Omega: return PlotPanel::tr("Angular velocities");
  case QuantityKind::Alpha: return PlotPanel::tr("Angular accelerations");
  }
  return {};
}

} // namespace

PlotPanel::PlotPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_selector(new QuantitySelector(this)),
      m_readout(new HoverReadout(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(m_selector);
  for (const QuantityKind kind : kKinds) {
    auto* view = new QuantityChartView(kind, titleOf(kind), this);
    view->setMinimumHeight(160);
    connect(view, &QuantityChartView::curveHovered, this,
            [this](PlotQuantity q, QPointF p, bool inside) { m_readout->showPoint(q, p, m_unit, inside); });
    connect(view, &QuantityChartView::resized, this, &PlotPanel::alignCharts);
    m_views[static_cast<std::size_t>(kind)] = view;
    layout->addWidget(view, 1);
  }
  layout->addWidget(m_readout);
  QuantityChartView* angles = chartView(QuantityKind::Angle);
  m_limits = std::make_unique<LimitMarkers>(angles->chart(), angles->xAxis(), angles->yAxis());

  connect(m_selector, &QuantitySelector::selectionChanged, this, &PlotPanel::onSelectionChanged);
  connect(m_document, &MechanismDocument::changed, this, &PlotPanel::onDocumentChanged);
  // Ask for exactly what the default selection shows, and plot it.
  applySelection();
}

// m_limits goes before the QWidget base deletes the charts, and touches none of them.
PlotPanel::~PlotPanel() = default;

void PlotPanel::setAngleUnit(AngleUnit unit) {
  if (unit == m_unit) return;
  m_unit = unit;
  m_readout->clearPoint();
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
  if (what & (Changes(Change::Design) | Change::Request))
    refreshData();
  else if (what & Change::Motion)
    refreshCursor();
}

void PlotPanel::onSelectionChanged() {
  applySelection();
  emit selectionChanged();
}

void PlotPanel::applySelection() {
  const kinematics::SolveRequest wanted = requestFor(selection());
  // A new request re-sweeps and comes back as Change::Request, which re-plots; otherwise
  // only the visibility changed and the current sweep serves.
  if (wanted != m_document->request())
    m_document->setRequest(wanted);
  else
    refreshData();
}

void PlotPanel::refreshData() {
  const kinematics::FourBarDesign& design = m_document->design();
  const kinematics::SweepResult& sweep = m_document->sweep();
  const QuantitySelection shown = selection();
  for (QuantityChartView* view : m_views) {
    view->setVisible(shown.any(view->kind()));
    view->setData(sweep, shown, m_unit, design.fromDeg, design.toDeg);
  }
  QuantityChartView* angles = chartView(QuantityKind::Angle);
  m_limits->setYSpan(angles->valueRange().min, angles->valueRange().max);
  m_limits->setPositions(
      limitMarkerPoints(m_document->analysis().limits, sweep, design.fromDeg, design.toDeg, m_unit),
      shown.contains(PlotQuantity::RockerAngle));
  refreshCursor();
  alignCharts();  // axis labels may have changed width
}

void PlotPanel::alignCharts() {
  QList<QChart*> shown;
  for (QuantityChartView* view : m_views)
    if (!view->isHidden()) shown.append(view->chart());
  alignPlotAreas(shown);
}

void PlotPanel::refreshCursor() {
  const kinematics::FourBarDesign& design = m_document->design();
  const std::optional<double> xDeg =
      wrapIntoRange(kinematics::radToDeg(m_document->crankAngle()), design.fromDeg, design.toDeg);
  const std::optional<double> x =
      xDeg ? std::optional<double>(toAngleUnit(kinematics::degToRad(*xDeg), m_unit)) : std::nullopt;
  for (QuantityChartView* view : m_views) view->setCursorX(x);
}

} // namespace linkwright::ui
