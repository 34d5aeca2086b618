#include "ui/classroom/polygon_view.h"

#include "ui/colors.h"

#include "ui/classroom/polygon_scale.h"
#include "ui/classroom/vector_label.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// Room around the drawing, in pixels at presentation scale 1: the title and legend above, the
// scale bar below, labels at the sides.
constexpr double kSideMargin = 36.0;
constexpr double kTopMargin = 58.0;
constexpr double kBottomMargin = 46.0;
constexpr double kHeadLength = 10.0;
constexpr double kLabelGap = 5.0;

// Where a polygon's box sits in the plane (its centre) and how big it is; a polygon at rest
// is a point.
Eigen::Vector2d boxCentre(const k::VectorPolygon& p) { return 0.5 * (p.lower + p.upper); }

bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const k::VectorPolygon& p) {
  return (a - b).norm() <= 1e-9 * std::max((p.upper - p.lower).norm(), 1e-300);
}

}  // namespace

QColor polygonTermColor(k::VectorTerm term) {
  const auto index = static_cast<std::size_t>(term);
  const auto& terms = colors().polygonTerms;
  return index < terms.size() ? terms[index] : colors().label;
}

QString polygonTermName(k::VectorTerm term) {
  switch (term) {
  case k::VectorTerm::Absolute: return PolygonView::tr("absolute");
  case k::VectorTerm::Relative: return PolygonView::tr("relative");
  case k::VectorTerm::Normal: return PolygonView::tr("normal");
  case k::VectorTerm::Tangential: return PolygonView::tr("tangential");
  case k::VectorTerm::Sliding: return PolygonView::tr("sliding");
  case k::VectorTerm::Coriolis: return PolygonView::tr("Coriolis");
  }
  return {};
}

PolygonView::PolygonView(QWidget* parent) : QWidget(parent) {
  setObjectName("PolygonView");
  setAutoFillBackground(true);
  QPalette pal = palette();
  pal.setColor(QPalette::Window, Qt::white);
  setPalette(pal);
}

void PolygonView::setPolygon(const k::VectorPolygon& polygon) {
  m_polygon = polygon;
  update();
}

void PolygonView::setChosenScale(double unitsPerCm) {
  m_chosenScale = std::isfinite(unitsPerCm) && unitsPerCm > 0.0 ? unitsPerCm : 0.0;
  update();
}

double PolygonView::pixelsPerCm() const { return logicalDpiX() / 2.54; }

double PolygonView::fitScale() const {
  const double ps = m_presentationScale;
  const QSize s = size().isEmpty() ? sizeHint() : size();
  const double widthCm = std::max(s.width() - 2.0 * kSideMargin * ps, 40.0) / pixelsPerCm();
  const double heightCm = std::max(s.height() - (kTopMargin + kBottomMargin) * ps, 40.0) / pixelsPerCm();
  const Eigen::Vector2d extent = m_polygon.upper - m_polygon.lower;
  return roundScaleAtLeast(std::max(extent.x() / widthCm, extent.y() / heightCm));
}

double PolygonView::scale() const { return m_chosenScale > 0.0 ? m_chosenScale : fitScale(); }

void PolygonView::setRevealedStep(int step) {
  m_revealed = std::max(step, 0);
  update();
}

std::vector<k::PolygonVector> PolygonView::drawnVectors() const {
  std::vector<k::PolygonVector> drawn;
  for (const k::PolygonVector& v : m_polygon.vectors)
    if (v.step <= m_revealed) drawn.push_back(v);
  return drawn;
}

std::vector<k::PolygonImage> PolygonView::drawnImages() const {
  const std::vector<k::PolygonVector> drawn = drawnVectors();
  std::vector<k::PolygonImage> images;
  for (const k::PolygonImage& im : m_polygon.images) {
    const bool pole = im.label == "o";
    const bool reached = std::any_of(drawn.begin(), drawn.end(),
                                     [&](const k::PolygonVector& v) { return near(v.to, im.position, m_polygon); });
    if (pole || reached) images.push_back(im);
  }
  return images;
}

void PolygonView::setPresentationScale(double scale) {
  m_presentationScale = std::clamp(scale, 0.5, 4.0);
  update();
}

// Presentation mode enlarges the window's font, which the view inherits: text follows it, and
// the presentation scale thickens lines and widens margins.
QFont PolygonView::scaledFont() const { return font(); }

QPointF PolygonView::toPixels(const Eigen::Vector2d& p) const {
  const double ps = m_presentationScale;
  const double pixelsPerUnit = pixelsPerCm() / scale();
  const Eigen::Vector2d d = (p - boxCentre(m_polygon)) * pixelsPerUnit;
  const double cx = width() / 2.0;
  const double cy = kTopMargin * ps + (height() - (kTopMargin + kBottomMargin) * ps) / 2.0;
  return {cx + d.x(), cy - d.y()};  // the polygon plane has y up
}

void PolygonView::drawArrow(QPainter& painter, const k::PolygonVector& v) const {
  const double ps = m_presentationScale;
  const QPointF a = toPixels(v.from);
  const QPointF b = toPixels(v.to);
  const QPointF d = b - a;
  const double length = std::hypot(d.x(), d.y());
  if (length < 0.5) return;  // a zero term (a crank at constant speed: A^t_B) has no arrow
  const QColor colour = polygonTermColor(v.term);
  const QPointF u = d / length;
  const QPointF n(u.y(), -u.x());
  const double head = std::min(kHeadLength * ps, 0.45 * length);
  painter.setPen(QPen(colour, 2.0 * ps, Qt::SolidLine, Qt::RoundCap));
  painter.drawLine(a, b - u * head * 0.8);
  QPainterPath tip;
  tip.moveTo(b);
  tip.lineTo(b - u * head + n * head * 0.38);
  tip.lineTo(b - u * head - n * head * 0.38);
  tip.closeSubpath();
  painter.setPen(Qt::NoPen);
  painter.setBrush(colour);
  painter.drawPath(tip);
}

double LabelLayout::cost(const QRectF& box) const {
  const QRectF padded = box.adjusted(-2, -2, 2, 2);
  if (!bounds.contains(padded)) return 1e6;
  double cost = 0.0;
  for (const QRectF& r : boxes)
    if (r.intersects(padded)) cost += 100.0;
  for (const QLineF& line : lines)
    for (int i = 0; i <= 24; ++i)
      if (padded.contains(line.pointAt(i / 24.0))) cost += 1.0;
  return cost;
}

QRectF LabelLayout::place(const std::vector<QRectF>& candidates) {
  QRectF best = candidates.front();
  double bestCost = cost(best);
  for (const QRectF& box : candidates) {
    if (bestCost == 0.0) break;
    const double c = cost(box);
    if (c < bestCost) {
      best = box;
      bestCost = c;
    }
  }
  boxes.push_back(best);
  return best;
}

void PolygonView::drawImages(QPainter& painter, LabelLayout& layout) const {
  const double ps = m_presentationScale;
  const double r = 3.5 * ps;
  const std::vector<k::PolygonImage> images = drawnImages();
  for (const k::PolygonImage& im : images) {
    const QPointF p = toPixels(im.position);
    painter.setPen(QPen(Qt::black, 1.2 * ps));
    painter.setBrush(im.coincident ? QBrush(Qt::white) : QBrush(Qt::black));
    painter.drawEllipse(p, r, r);
    layout.boxes.push_back(QRectF(p.x() - r, p.y() - r, 2 * r, 2 * r));
  }
  QFont bold = painter.font();
  bold.setBold(true);
  painter.setFont(bold);
  const QFontMetricsF fm(bold);
  painter.setPen(Qt::black);
  for (const k::PolygonImage& im : images) {
    const QPointF p = toPixels(im.position);
    const QString text = QString::fromStdString(im.label);
    const QSizeF size(fm.horizontalAdvance(text) + 2.0, fm.height());
    const double off = r + 1.0 * ps;
    std::vector<QRectF> candidates;
    for (const QPointF corner : {QPointF(1, -1), QPointF(-1, -1), QPointF(1, 1), QPointF(-1, 1)})
      candidates.emplace_back(QPointF(p.x() + (corner.x() > 0 ? off : -off - size.width()),
                                      p.y() + (corner.y() > 0 ? off : -off - size.height())),
                              size);
    painter.drawText(layout.place(candidates), Qt::AlignCenter, text);
  }
  painter.setFont(scaledFont());
}

// Each label beside its arrow where it hides no other label, image or line: at the middle
// first, then further along, on either side.
void PolygonView::drawVectorLabels(QPainter& painter, LabelLayout& layout) const {
  const double gap = kLabelGap * m_presentationScale;
  QFont larger = painter.font();
  larger.setPointSizeF(larger.pointSizeF() * 1.15);
  painter.setFont(larger);
  for (const k::PolygonVector& v : drawnVectors()) {
    const QPointF a = toPixels(v.from);
    const QPointF d = toPixels(v.to) - a;
    const double length = std::hypot(d.x(), d.y());
    if (length < 0.5) continue;
    const QPointF n(d.y() / length, -d.x() / length);
    const QString label = QString::fromStdString(v.label);
    std::vector<QRectF> candidates;
    for (const double away : {gap, 3.0 * gap})
      for (const double t : {0.5, 0.35, 0.65, 0.2, 0.8})
        for (const double side : {1.0, -1.0})
          candidates.push_back(vectorLabelRect(painter.font(), label, a + t * d, side * n, away));
    drawVectorLabel(painter, label, layout.place(candidates), polygonTermColor(v.term));
  }
  painter.setFont(scaledFont());
}

void PolygonView::drawScaleBar(QPainter& painter) const {
  const double ps = m_presentationScale;
  const double cm = pixelsPerCm();
  const double x0 = kSideMargin * ps * 0.5;
  const double y = height() - kBottomMargin * ps * 0.45;
  painter.setPen(QPen(Qt::black, 1.5 * ps));
  painter.drawLine(QPointF(x0, y), QPointF(x0 + 2.0 * cm, y));
  for (int i = 0; i <= 2; ++i) painter.drawLine(QPointF(x0 + i * cm, y - 4 * ps), QPointF(x0 + i * cm, y + 4 * ps));
  const QString text =
      scaleText(scale(), QString::fromStdString(m_polygon.unit)) + (m_chosenScale > 0.0 ? QString() : tr("  (fit)"));
  painter.drawText(QPointF(x0 + 2.0 * cm + 10.0 * ps, y + painter.fontMetrics().ascent() / 2.0 - 1.0), text);
}

void PolygonView::drawLegend(QPainter& painter) const {
  const double ps = m_presentationScale;
  const QFontMetricsF fm(painter.font());
  QFont title = painter.font();
  title.setBold(true);
  painter.setFont(title);
  painter.setPen(Qt::black);
  const bool velocity = m_polygon.kind == k::PolygonKind::Velocity;
  const QString heading = (velocity ? tr("Velocity polygon") : tr("Acceleration polygon")) +
                          QStringLiteral(" (%1)").arg(QString::fromStdString(m_polygon.unit));
  painter.drawText(QPointF(8.0 * ps, 6.0 * ps + fm.ascent()), heading);
  painter.setFont(scaledFont());
  double x = 8.0 * ps;
  const double y = 12.0 * ps + 1.9 * fm.height();
  for (const k::VectorTerm term : {k::VectorTerm::Absolute, k::VectorTerm::Relative, k::VectorTerm::Normal,
                                   k::VectorTerm::Tangential, k::VectorTerm::Sliding, k::VectorTerm::Coriolis}) {
    const bool present = std::any_of(m_polygon.vectors.begin(), m_polygon.vectors.end(),
                                     [&](const k::PolygonVector& v) { return v.term == term; });
    if (!present) continue;
    painter.setPen(QPen(polygonTermColor(term), 3.0 * ps));
    painter.drawLine(QPointF(x, y - fm.ascent() / 3.0), QPointF(x + 16.0 * ps, y - fm.ascent() / 3.0));
    painter.setPen(Qt::black);
    const QString name = polygonTermName(term);
    painter.drawText(QPointF(x + 20.0 * ps, y), name);
    x += 20.0 * ps + fm.horizontalAdvance(name) + 12.0 * ps;
  }
}

void PolygonView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  emit resized();
}

void PolygonView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QFont f = scaledFont();
  painter.setFont(f);
  if (m_polygon.vectors.empty()) return;
  LabelLayout layout;
  layout.bounds = QRectF(rect());
  for (const k::PolygonVector& v : drawnVectors()) {
    drawArrow(painter, v);
    layout.lines.emplace_back(toPixels(v.from), toPixels(v.to));
  }
  drawImages(painter, layout);
  drawVectorLabels(painter, layout);
  painter.setFont(f);
  drawScaleBar(painter);
  drawLegend(painter);
}

}  // namespace linkwright::ui
