#include "ui/classroom/atlas_cell_view.h"

#include "ui/geometry.h"
#include "ui/number_text.h"

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/model/units.h"

#include <QFontMetrics>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kLabelHeight = 30;
constexpr int kMargin = 6;

QString number(double v) { return numberText(v, 'g', 3); }
QString point(const Eigen::Vector2d& p) { return pointText(p.x(), p.y(), 3); }
QString degrees(double rad) { return numberText(k::radToDeg(rad), 'f', 1) + QStringLiteral("°"); }

// The samples from `first` to `last` (wrapping), as drawn.
QPolygonF run(const QPolygonF& curve, std::size_t first, std::size_t last) {
  QPolygonF out;
  const auto n = static_cast<std::size_t>(curve.size());
  if (n == 0) return out;
  for (std::size_t i = first;; i = (i + 1) % n) {
    out << curve[static_cast<qsizetype>(i)];
    if (i == last || static_cast<std::size_t>(out.size()) > n) break;
  }
  return out;
}

}  // namespace

QString atlasCellDescription(const k::AtlasCell& cell) {
  const k::FourBarLengths& l = cell.key.lengths;
  QString text = AtlasCellView::tr(
                     "Crank 1, coupler %1, rocker %2, frame %3; P %4 along and %5 across the coupler "
                     "(coupler lengths). %6, the crank %7.")
                     .arg(number(l.coupler), number(l.rocker), number(l.frame), number(cell.key.point.along),
                          number(cell.key.point.across), QString::fromUtf8(k::toString(cell.grashof.category).data()),
                          QString::fromUtf8(k::toString(cell.motion).data()));
  if (cell.motion == k::CrankMotion::NeverAssembles) return text;
  const k::CurveFeatures& f = cell.features;
  for (const k::Cusp& c : f.cusps)
    text += AtlasCellView::tr("\nCusp at crank %1, at %2.").arg(degrees(c.crankAngle), point(c.point));
  for (const k::Crunode& c : f.crunodes)
    text += AtlasCellView::tr("\nCrunode at %1, passed at crank %2 and %3.")
                .arg(point(c.point), degrees(c.crankAngles[0]), degrees(c.crankAngles[1]));
  if (f.symmetry)
    text += AtlasCellView::tr("\nSymmetric about the line through %1 along (%2, %3).")
                .arg(point(f.symmetry->point), number(f.symmetry->direction.x()), number(f.symmetry->direction.y()));
  if (f.straight)
    text += AtlasCellView::tr("\nStraight from crank %1 to %2: %3 long, within %4.")
                .arg(degrees(f.straight->fromAngle), degrees(f.straight->toAngle), number(f.straight->length),
                     number(f.straight->deviation));
  if (f.circular)
    text += AtlasCellView::tr("\nCircular from crank %1 to %2: radius %3 about %4, within %5.")
                .arg(degrees(f.circular->fromAngle), degrees(f.circular->toAngle), number(f.circular->radius),
                     point(f.circular->centre), number(f.circular->deviation));
  return text + AtlasCellView::tr("\nClick to make it the design.");
}

AtlasCellView::AtlasCellView(std::size_t index, const k::AtlasCellKey& key, QWidget* parent)
    : QWidget(parent), m_index(index), m_key(key) {
  setFixedSize(kSide, kSide);
  setCursor(Qt::PointingHandCursor);
  setToolTip(tr("Computing…"));
}

void AtlasCellView::setCell(const k::AtlasCell& cell) {
  m_cell = cell;
  m_curve.clear();
  for (const Eigen::Vector2d& p : cell.curve.point) m_curve << toQt(p);
  setToolTip(atlasCellDescription(cell));
  update();
}

QString AtlasCellView::label() const {
  const k::FourBarLengths& l = m_key.lengths;
  QString text = QStringLiteral("%1 · %2 · %3  P(%4, %5)")
                     .arg(number(l.coupler), number(l.rocker), number(l.frame), number(m_key.point.along),
                          number(m_key.point.across));
  if (!m_cell) return text + QLatin1Char('\n') + tr("computing…");
  if (m_cell->motion == k::CrankMotion::NeverAssembles) return text + QLatin1Char('\n') + tr("never assembles");
  QStringList names;
  for (const std::string& name : k::featureNames(m_cell->features)) names << QString::fromStdString(name);
  if (m_cell->motion == k::CrankMotion::Rocks) names.prepend(tr("rocks"));
  return text + QLatin1Char('\n') + (names.isEmpty() ? tr("—") : names.join(QStringLiteral(", ")));
}

QFont AtlasCellView::labelFont() const {
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.8);
  return small;
}

QStringList AtlasCellView::shownLabel() const {
  const QFontMetrics metrics(labelFont());
  QStringList lines = label().split(QLatin1Char('\n'));
  for (QString& line : lines) line = metrics.elidedText(line, Qt::ElideRight, width() - 4);
  return lines;
}

QTransform AtlasCellView::modelToWidget() const {
  const QRectF box = m_curve.boundingRect();
  const QRectF area(kMargin, kMargin, width() - 2 * kMargin, height() - kLabelHeight - 2 * kMargin);
  const double span = std::max({box.width(), box.height(), 1e-9});
  const double scale = std::min(area.width(), area.height()) / span;
  // y up: the model's top is the widget's top.
  QTransform t;
  t.translate(area.center().x(), area.center().y());
  t.scale(scale, -scale);
  t.translate(-box.center().x(), -box.center().y());
  return t;
}

void AtlasCellView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), palette().base());
  painter.setPen(palette().mid().color());
  painter.drawRect(rect().adjusted(0, 0, -1, -1));
  painter.setPen(palette().text().color());
  painter.setFont(labelFont());
  painter.drawText(QRectF(2, height() - kLabelHeight, width() - 4, kLabelHeight), Qt::AlignCenter,
                   shownLabel().join(QLatin1Char('\n')));
  if (m_curve.size() < 2) return;
  const QTransform t = modelToWidget();
  painter.setPen(QPen(palette().text().color(), 1.2));
  painter.drawPolygon(t.map(m_curve));
  drawFeatures(painter, t);
}

void AtlasCellView::drawFeatures(QPainter& painter, const QTransform& t) const {
  const k::CurveFeatures& f = m_cell->features;
  if (f.symmetry) {
    const double reach = f.size;
    const Eigen::Vector2d a = f.symmetry->point - reach * f.symmetry->direction;
    const Eigen::Vector2d b = f.symmetry->point + reach * f.symmetry->direction;
    painter.save();
    painter.setClipRect(QRectF(0, 0, width(), height() - kLabelHeight));
    painter.setPen(QPen(QColor(128, 128, 128), 1.0, Qt::DashLine));
    painter.drawLine(t.map(toQt(a)), t.map(toQt(b)));
    painter.restore();
  }
  if (f.straight) {
    painter.setPen(QPen(QColor(0, 150, 60), 3.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawPolyline(t.map(run(m_curve, f.straight->firstSample, f.straight->lastSample)));
  }
  if (f.circular) {
    painter.setPen(QPen(QColor(230, 130, 0, 200), 3.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawPolyline(t.map(run(m_curve, f.circular->firstSample, f.circular->lastSample)));
  }
  painter.setPen(QPen(QColor(30, 90, 220), 1.5));
  painter.setBrush(Qt::NoBrush);
  for (const k::Crunode& c : f.crunodes) painter.drawEllipse(t.map(toQt(c.point)), 4.0, 4.0);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(220, 30, 30));
  for (const k::Cusp& c : f.cusps) painter.drawEllipse(t.map(toQt(c.point)), 3.5, 3.5);
}

void AtlasCellView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint())) emit clicked(m_index);
}

}  // namespace linkwright::ui
