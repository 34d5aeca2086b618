#include "ui/plots/plot_axes.h"

#include "ui/plots/axis_range.h"
#include "ui/plots/plot_grid.h"

#include <QChart>
#include <QFontMetricsF>
#include <QPainter>
#include <QStyleOptionGraphicsItem>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace {

// Qt Charts' axis layer (ChartPresenter::AxisZValue): above the grid, below the series.
constexpr qreal kAxesZ = 3.0;
// Qt Charts' spacing (ChartAxisElement): a tick is as long as the gap from it to its label.
constexpr qreal kLabelPadding = 4.0;
constexpr qreal kTitlePadding = 2.0;
constexpr int kTickLength = 4;  // = kLabelPadding, in whole pixels
// Qt Charts drew its texts as documents with this margin all round (ChartPresenter::textMargin);
// the same space keeps the labels and titles as far apart as they were.
constexpr qreal kTextMargin = 4.0;

// From this size on a label prints in scientific notation: in fixed notation a value near a
// toggle position could print hundreds of digits and squash the plot to nothing.
constexpr double kLargestFixed = 1e9;

// `value` as the axis's "%.Nf" label format prints it (any other format: the digits `step`
// needs); a rounding error about zero prints as 0, not -0.
QString formatLabel(double value, const QString& format, double step) {
  if (std::abs(value) >= kLargestFixed) return QString::number(value, 'g', 6);
  const bool fixed = format.size() == 4 && format.startsWith(QLatin1String("%.")) && format[2].isDigit() &&
                     format[3] == QLatin1Char('f');
  const int decimals = fixed ? format[2].digitValue() : decimalsFor(step);
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
  return QString::number(value, 'f', decimals);
}

QStaticText staticText(const QString& text, const QFont& font) {
  QStaticText s(text);
  s.setTextFormat(Qt::PlainText);
  s.prepare(QTransform(), font);
  return s;
}

int ceilPx(double px) { return static_cast<int>(std::ceil(px - 1e-6)); }

// The axis pen's width in whole pixels, at least one.
int lineWidth(const QValueAxis& axis) { return std::max(1, static_cast<int>(std::lround(axis.linePen().widthF()))); }

}  // namespace

PlotAxesItem::PlotAxesItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis)
    : QGraphicsObject(chart), m_chart(chart), m_x{xAxis, {}, {}}, m_y{yAxis, {}, {}}, m_area(chart->plotArea()) {
  setZValue(kAxesZ);
  setAcceptedMouseButtons(Qt::NoButton);  // the curves' hover and the view's gestures pass through
  setFlag(ItemUsesExtendedStyleOption);   // paint() reads the exposed rectangle
  follow(xAxis);
  follow(yAxis);
  connect(chart, &QChart::plotAreaChanged, this, [this](const QRectF& area) {
    prepareGeometryChange();
    m_area = area;
    retitle(m_x, area.width());
    retitle(m_y, area.height());
  });
  relabel();
}

void PlotAxesItem::follow(QValueAxis* axis) {
  // Qt Charts' own items go: a hidden axis is left out of the chart's layout and is not laid
  // out for a new range, but it still scales the series and names what this item draws.
  axis->setVisible(false);
  axis->setTitleVisible(false);  // shown on a hidden axis, Qt would draw it unplaced: setTitleShown()
  const auto relabelled = [this] { relabel(); };
  connect(axis, &QValueAxis::rangeChanged, this, relabelled);
  connect(axis, &QValueAxis::tickCountChanged, this, relabelled);
  connect(axis, &QValueAxis::tickIntervalChanged, this, relabelled);
  connect(axis, &QValueAxis::tickAnchorChanged, this, relabelled);
  connect(axis, &QValueAxis::tickTypeChanged, this, relabelled);
  connect(axis, &QValueAxis::labelFormatChanged, this, relabelled);
  connect(axis, &QAbstractAxis::reverseChanged, this, relabelled);
  connect(axis, &QAbstractAxis::labelsFontChanged, this, relabelled);
  connect(axis, &QAbstractAxis::labelsVisibleChanged, this, relabelled);
  connect(axis, &QAbstractAxis::titleFontChanged, this, relabelled);
  connect(axis, &QAbstractAxis::titleTextChanged, this, relabelled);
  connect(axis, &QAbstractAxis::titleVisibleChanged, this, relabelled);
  const auto repaint = [this] { update(); };
  connect(axis, &QAbstractAxis::linePenChanged, this, repaint);
  connect(axis, &QAbstractAxis::labelsBrushChanged, this, repaint);
  connect(axis, &QAbstractAxis::titleBrushChanged, this, repaint);
}

QString fittedTitle(const QString& title, const QFontMetricsF& metrics, double length) {
  if (metrics.horizontalAdvance(title) <= length) return title;
  // A title longer than its side of the plot loses its name, never its unit: "angle […" at a
  // short chart's side said neither what nor in what. The name is cut short with "…", then
  // left out; the unit is drawn whole even where it is longer than the side (into the margins).
  const auto bracket = title.lastIndexOf(QLatin1Char('['));
  if (bracket <= 0) return metrics.elidedText(title, Qt::ElideRight, std::max(0.0, length));
  const QString unit = title.mid(bracket);
  const QString name = title.left(bracket).trimmed();
  const double room = length - metrics.horizontalAdvance(QLatin1Char(' ') + unit);
  const QString shortName = metrics.elidedText(name, Qt::ElideRight, std::max(0.0, room));
  // An elided name that is only "…" says nothing: then the unit alone.
  if (shortName.isEmpty() || shortName == QStringLiteral("…")) return unit;
  return shortName + QLatin1Char(' ') + unit;
}

void PlotAxesItem::relabel(Axis& axis) const {
  axis.labels.clear();
  axis.widest = 0.0;
  if (!axis.axis->labelsVisible()) return;
  const QFont font = axis.axis->labelsFont();
  const QFontMetricsF metrics(font);
  const QString format = axis.axis->labelFormat();
  const std::vector<double> values = majorTickValues(*axis.axis);
  const double step = values.size() > 1 ? values[1] - values[0] : 1.0;
  for (const double value : values) {
    const QString text = formatLabel(value, format, step);
    axis.widest = std::max(axis.widest, metrics.horizontalAdvance(text));
    axis.labels.push_back(staticText(text, font));
  }
}

void PlotAxesItem::retitle(Axis& axis, double length) const {
  const QString title = axis.titled ? axis.axis->titleText() : QString();
  const QFont font = axis.axis->titleFont();
  axis.title = staticText(fittedTitle(title, QFontMetricsF(font), length), font);
}

void PlotAxesItem::relabel() {
  relabel(m_x);
  relabel(m_y);
  retitle(m_x, m_area.width());
  retitle(m_y, m_area.height());
  // How deep the labels reach away from the plot area: a line of text below it, the widest
  // label beside it.
  m_x.depth = m_x.labels.empty() ? 0.0 : QFontMetricsF(m_x.axis->labelsFont()).height();
  m_y.depth = m_y.labels.empty() ? 0.0 : m_y.widest;
  const double yLabelHeight = QFontMetricsF(m_y.axis->labelsFont()).height();
  // The end labels reach past the plot area by half their size: the top one above it, the
  // last one on the right beside it.
  setRoom(QMargins(ceilPx(reach(m_y)), ceilPx(m_y.labels.empty() ? 0.0 : 0.5 * yLabelHeight), ceilPx(0.5 * m_x.widest),
                   ceilPx(reach(m_x))));
  update();
}

double PlotAxesItem::titleOffset(const Axis& axis) {
  const double labels = axis.depth > 0.0 ? axis.depth + kTextMargin : 0.0;
  return kLabelPadding + labels + kTitlePadding + kTextMargin;
}

double PlotAxesItem::reach(const Axis& axis) {
  const bool titled = axis.titled && !axis.axis->titleText().isEmpty();
  if (!titled) return kLabelPadding + (axis.depth > 0.0 ? axis.depth + kTextMargin : 0.0);
  return titleOffset(axis) + QFontMetricsF(axis.axis->titleFont()).height() + kTextMargin + kTitlePadding;
}

void PlotAxesItem::setRoom(const QMargins& room) {
  if (room == m_room) return;
  prepareGeometryChange();
  m_chart->setMargins(m_chart->margins() - m_room + room);
  m_room = room;
}

QStringList PlotAxesItem::labels(Qt::Orientation orientation) const {
  QStringList texts;
  for (const QStaticText& label : (orientation == Qt::Horizontal ? m_x : m_y).labels) texts.append(label.text());
  return texts;
}

QString PlotAxesItem::title(Qt::Orientation orientation) const {
  return (orientation == Qt::Horizontal ? m_x : m_y).title.text();
}

void PlotAxesItem::setTitleShown(Qt::Orientation orientation, bool shown) {
  Axis& axis = orientation == Qt::Horizontal ? m_x : m_y;
  if (axis.titled == shown) return;
  axis.titled = shown;
  relabel();
}

bool PlotAxesItem::titleShown(Qt::Orientation orientation) const {
  return (orientation == Qt::Horizontal ? m_x : m_y).titled;
}

QRectF PlotAxesItem::boundingRect() const {
  return m_area.adjusted(-m_room.left() - 1.0, -m_room.top() - 1.0, m_room.right() + 1.0, m_room.bottom() + 1.0);
}

void PlotAxesItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*) {
  if (m_area.isEmpty()) return;
  // A drag repaints the plot area, which only the axis lines border: the labels and titles
  // outside it are drawn only where the view asks for them.
  paintX(painter, option->exposedRect);
  paintY(painter, option->exposedRect);
}

void PlotAxesItem::paintX(QPainter* painter, const QRectF& exposed) const {
  const QValueAxis& axis = *m_x.axis;
  const double bottom = m_area.bottom();
  const std::vector<double> ticks = majorTickPixels(axis, m_area.left(), m_area.right());
  // Filled rows and columns of pixels, as the grid's (plot_grid.h): no stroker for a line.
  const QBrush line = axis.linePen().brush();
  const int width = lineWidth(axis), row = gridPixel(bottom), left = gridPixel(m_area.left());
  painter->fillRect(QRect(left, row, gridPixel(m_area.right()) - left + 1, width), line);
  for (const double x : ticks) painter->fillRect(QRect(gridPixel(x), row, width, kTickLength), line);
  // A static text is drawn in the painter's font: the one it was laid out in.
  painter->setPen(axis.labelsBrush().color());
  painter->setFont(axis.labelsFont());
  for (std::size_t i = 0; i < m_x.labels.size() && i < ticks.size(); ++i) {
    const QStaticText& text = m_x.labels[i];
    const QRectF at(QPointF(ticks[i] - 0.5 * text.size().width(), bottom + kLabelPadding), text.size());
    if (exposed.intersects(at)) painter->drawStaticText(at.topLeft(), text);
  }
  if (m_x.title.text().isEmpty()) return;
  const QRectF at(QPointF(m_area.center().x() - 0.5 * m_x.title.size().width(), bottom + titleOffset(m_x)),
                  m_x.title.size());
  if (!exposed.intersects(at)) return;
  painter->setPen(axis.titleBrush().color());
  painter->setFont(axis.titleFont());
  painter->drawStaticText(at.topLeft(), m_x.title);
}

void PlotAxesItem::paintY(QPainter* painter, const QRectF& exposed) const {
  const QValueAxis& axis = *m_y.axis;
  const double left = m_area.left();
  const std::vector<double> ticks = majorTickPixels(axis, m_area.bottom(), m_area.top());
  const QBrush line = axis.linePen().brush();
  const int width = lineWidth(axis), edge = gridPixel(left), top = gridPixel(m_area.top());
  painter->fillRect(QRect(edge, top, width, gridPixel(m_area.bottom()) - top + 1), line);
  for (const double y : ticks) painter->fillRect(QRect(edge - kTickLength, gridPixel(y), kTickLength, width), line);
  painter->setPen(axis.labelsBrush().color());
  painter->setFont(axis.labelsFont());
  for (std::size_t i = 0; i < m_y.labels.size() && i < ticks.size(); ++i) {
    const QStaticText& text = m_y.labels[i];
    const QSizeF size = text.size();
    const QRectF at(QPointF(left - kLabelPadding - size.width(), ticks[i] - 0.5 * size.height()), size);
    if (exposed.intersects(at)) painter->drawStaticText(at.topLeft(), text);
  }
  if (m_y.title.text().isEmpty()) return;
  // Read from below, as Qt Charts set it: turned a quarter turn anticlockwise, its top towards
  // the labels.
  const QSizeF size = m_y.title.size();
  const double column = left - titleOffset(m_y) - QFontMetricsF(axis.titleFont()).height();
  if (!exposed.intersects(QRectF(column, m_area.center().y() - 0.5 * size.width(), size.height(), size.width())))
    return;
  painter->setPen(axis.titleBrush().color());
  painter->setFont(axis.titleFont());
  painter->save();
  painter->translate(column, m_area.center().y());
  painter->rotate(-90.0);
  painter->drawStaticText(QPointF(-0.5 * size.width(), 0.0), m_y.title);
  painter->restore();
}

QMargins axesRoom(const QChart* chart) {
  const PlotAxesItem* axes = plotAxes(chart);
  return axes != nullptr ? axes->room() : QMargins();
}

PlotAxesItem* plotAxes(const QChart* chart) {
  for (QGraphicsItem* item : chart->childItems())
    if (auto* axes = dynamic_cast<PlotAxesItem*>(item)) return axes;
  return nullptr;
}

}  // namespace linkwright::ui
