#include "ui/plots/force_chart_view.h"

#include "ui/plots/chart_view_setup.h"
#include "ui/plots/crank_angle_chart.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/plot_quantity.h"

#include <QChart>
#include <QLegend>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace linkwright::ui {

ForceChartView::ForceChartView(const QString& title, bool fromZero, QWidget* parent)
    : QChartView(parent), m_fromZero(fromZero), m_xAxis(new QValueAxis), m_yAxis(new QValueAxis) {
  QChart* chart = makeCrankAngleChart(title, m_xAxis, m_yAxis);
  setChart(chart);
  setUpChartView(this);
  m_cursor = makeCrankCursor(chart, m_xAxis, m_yAxis);
  // The curves are simplified for the plot area's scale: a new one may need them drawn again.
  connect(chart, &QChart::plotAreaChanged, this, [this] {
    applyTickStep(m_xAxis, m_xRange, this->chart()->plotArea().width());
    for (SegmentedLine& line : m_lines) line.rescale();
  });
}

ForceChartView::~ForceChartView() = default;

void ForceChartView::setCurves(const std::vector<Curve>& curves) {
  const bool same = curves.size() == m_lines.size() &&
                    std::equal(curves.begin(), curves.end(), m_lines.begin(),
                               [](const Curve& a, const SegmentedLine& b) { return a == b.style(); });
  if (same) return;
  for (SegmentedLine& line : m_lines) line.removeFromChart();
  m_lines.clear();
  m_lines.reserve(curves.size());
  for (const Curve& c : curves) m_lines.emplace_back(chart(), m_xAxis, m_yAxis, c);
  chart()->legend()->setVisible(curves.size() > 1);
  m_cursor->raise();
}

bool ForceChartView::setData(const std::vector<SeriesRuns>& runs, const QString& valueTitle, const PlotXAxis& x,
                             DataFlow flow) {
  // The axes first: the curves are simplified for the scale they set (segmented_line.h).
  m_values.clear();
  for (const SeriesRuns& r : runs)
    for (const QList<QPointF>& run : r.runs)
      for (const QPointF& p : run) m_values.push_back(p.y());
  // Forces grow without bound next to a toggle: such spikes run off the chart rather than
  // squash every other value flat.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::tie(m_lo, m_hi) = m_values.empty() ? std::pair<double, double>{kInf, -kInf} : robustSpan(m_values);
  if (m_fromZero && !m_values.empty()) m_lo = std::min(m_lo, 0.0);
  // While the data change, the axis stays where it still serves (keepsRange).
  if (!m_yShown || !keepsRange(*m_yShown, m_lo, m_hi)) m_yShown = fittedRange(flow);
  const AxisRange y = *m_yShown;
  applyAxisRange(m_yAxis, y);
  if (m_yAxis->titleText() != valueTitle) m_yAxis->setTitleText(valueTitle);
  applyAxisRange(m_xAxis, x.range);
  m_xRange = x.range;
  applyTickStep(m_xAxis, x.range, chart()->plotArea().width());
  if (m_xAxis->titleText() != x.title) m_xAxis->setTitleText(x.title);
  m_cursor->setYSpan(y.min, y.max);
  static const SeriesRuns kNone;
  ChartLayoutInputs inputs{axesRoom(chart()), {}};
  for (std::size_t i = 0; i < m_lines.size(); ++i) {
    m_lines[i].setRuns(i < runs.size() ? runs[i] : kNone, true);
    inputs.legend.push_back(true);
  }
  return inputs.replace(m_layoutInputs);
}

AxisRange ForceChartView::fittedRange(DataFlow flow) const {
  AxisRange y = refittedRange(m_lo, m_hi, flow);
  if (m_fromZero && m_lo >= 0.0 && y.min < 0.0) {
    // Magnitudes: the axis starts at 0, not at the margin below it.
    y.min = 0.0;
    y.tickCount = static_cast<int>(std::lround(y.max / y.step)) + 1;
  }
  return y;
}

bool ForceChartView::settleValueRange() {
  const AxisRange fitted = fittedRange(DataFlow::Settled);
  if (m_yShown == fitted) return false;
  m_yShown = fitted;
  applyAxisRange(m_yAxis, fitted);
  m_cursor->setYSpan(fitted.min, fitted.max);
  for (SegmentedLine& line : m_lines) line.rescale();
  const QMargins before = std::exchange(m_layoutInputs.axesRoom, axesRoom(chart()));
  return m_layoutInputs.axesRoom != before;
}

void ForceChartView::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  emit resized();
}

void ForceChartView::setCursorX(std::optional<double> x) { m_cursor->setX(x); }

CurveItem* ForceChartView::curveItem(std::size_t index) const {
  return index < m_lines.size() ? m_lines[index].item() : nullptr;
}

QList<QPointF> ForceChartView::samples(std::size_t index) const {
  return index < m_lines.size() ? m_lines[index].samples() : QList<QPointF>{};
}

}  // namespace linkwright::ui
