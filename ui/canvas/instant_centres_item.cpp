#include "ui/canvas/instant_centres_item.h"

#include "ui/colors.h"

#include "ui/canvas/canvas_style.h"
#include "ui/geometry.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr double kCentreDotPx = 3.5;
constexpr double kFarArrowPx = 48.0;

// One centre with its label and, for drawing it as an arrow, the finite centre it leaves from
// (on the Kennedy line that locates it).
struct NamedCentre {
  const k::InstantCentre* centre;
  const k::InstantCentre* anchor;
  QString label;
};

std::array<NamedCentre, 6> named(const k::InstantCentres& c) {
  return {{{&c.i12, &c.i12, QStringLiteral("I₁₂")},
           {&c.i23, &c.i12, QStringLiteral("I₂₃")},
           {&c.i34, &c.i23, QStringLiteral("I₃₄")},
           {&c.i14, &c.i12, QStringLiteral("I₁₄")},
           {&c.i13, &c.i23, QStringLiteral("I₁₃")},
           {&c.i24, &c.i12, QStringLiteral("I₂₄")}}};
}

// A finite centre near enough to draw as a point (far ones run off the drawing).
bool near(const k::InstantCentre& centre, const k::InstantCentres& all) {
  return centre.kind == k::CentreKind::Finite &&
         (centre.position - all.i12.position).norm() <= k::kCentrodeReach * all.scale;
}

// A label on a white box, its bottom-right corner at `corner` (pixels): upper left of a
// centre, where the point names (upper right) and ground hatching (below) are not.
void drawLabel(QPainter* painter, const QPointF& corner, const QString& text) {
  const QFontMetricsF metrics(painter->font());
  const QRectF box(corner - QPointF(metrics.horizontalAdvance(text) + 4.0, metrics.height()), corner);
  painter->fillRect(box, colors().labelBox);
  painter->drawText(box, Qt::AlignCenter, text);
}

void drawArrow(QPainter* painter, const QPointF& from, const QPointF& unit, double length, double head) {
  const QPointF tip = from + unit * length;
  const QPointF side(-unit.y(), unit.x());
  painter->drawLine(from, tip);
  painter->drawLine(tip, tip - unit * head + side * 0.5 * head);
  painter->drawLine(tip, tip - unit * head - side * 0.5 * head);
}

}  // namespace

InstantCentresItem::InstantCentresItem(QGraphicsItem* parent) : QGraphicsItem(parent) { setZValue(canvas::z::kArrows); }

void InstantCentresItem::setCycle(const k::Mechanism& mechanism, const k::SweepResult& sweep) {
  auto curves = k::centrodes(mechanism, sweep);
  m_centrodes = curves ? std::move(curves).value() : k::Centrodes{};
  updateBounds();
}

void InstantCentresItem::setPose(const k::Mechanism& mechanism, const k::Pose& pose) {
  const auto centres = k::instantCentres(mechanism, pose);
  const auto frame = k::couplerFrame(mechanism, pose);
  m_centres.reset();
  m_frame.reset();
  m_reason.clear();
  if (!centres) m_reason = QString::fromStdString(centres.error().message);
  else m_centres = *centres;
  if (frame) m_frame = *frame;
  updateBounds();
}

void InstantCentresItem::setPresentationScale(double factor) {
  m_scale = factor;
  update();
}

void InstantCentresItem::updateBounds() {
  QRectF box;
  const auto include = [&](const Eigen::Vector2d& p) {
    const QPointF q = toQt(p);
    box = box.isNull() ? QRectF(q, QSizeF(0.0, 0.0)) : box.united(QRectF(q, QSizeF(0.0, 0.0)));
  };
  if (m_centres)
    for (const NamedCentre& c : named(*m_centres))
      if (near(*c.centre, *m_centres)) include(c.centre->position);
  for (const auto& run : m_centrodes.fixed)
    for (const Eigen::Vector2d& p : run) include(p);
  if (m_frame)
    for (const auto& run : m_centrodes.moving)
      for (const Eigen::Vector2d& p : run) include(m_frame->toWorld(p));
  // Marks, arrows and labels are drawn in pixels around these points.
  const double margin = 0.25 * std::max({box.width(), box.height(), m_centres ? m_centres->scale : 0.0});
  prepareGeometryChange();
  m_bounds = box.adjusted(-margin, -margin, margin, margin);
  update();
}

QRectF InstantCentresItem::boundingRect() const { return m_bounds; }

void InstantCentresItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const QTransform toPixels = painter->worldTransform();
  const auto px = [&](const Eigen::Vector2d& p) { return toPixels.map(toQt(p)); };
  painter->save();
  painter->resetTransform();
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setBrush(Qt::NoBrush);

  // The centrodes first, under everything: fixed solid, moving dashed on the coupler.
  painter->setPen(QPen(colors().centre, 1.5 * m_scale));
  for (const auto& run : m_centrodes.fixed) {
    QPolygonF line;
    for (const Eigen::Vector2d& p : run) line << px(p);
    painter->drawPolyline(line);
  }
  if (m_frame) {
    painter->setPen(QPen(colors().movingCentrode, 1.5 * m_scale, Qt::DashLine));
    for (const auto& run : m_centrodes.moving) {
      QPolygonF line;
      for (const Eigen::Vector2d& p : run) line << px(m_frame->toWorld(p));
      painter->drawPolyline(line);
    }
  }
  if (!m_centres) {
    painter->restore();
    return;
  }
  const k::InstantCentres& c = *m_centres;

  // Kennedy's lines: each holds three centres; drawn across the finite ones it holds.
  painter->setPen(QPen(colors().kennedyLine, 1.0 * m_scale, Qt::DashLine));
  const std::array<std::array<const k::InstantCentre*, 3>, 4> lines{
      {{&c.i12, &c.i23, &c.i13}, {&c.i14, &c.i34, &c.i13}, {&c.i12, &c.i14, &c.i24}, {&c.i23, &c.i34, &c.i24}}};
  for (const auto& line : lines) {
    std::vector<QPointF> points;
    for (const k::InstantCentre* centre : line)
      if (near(*centre, c)) points.push_back(px(centre->position));
    double longest = 0.0;
    QLineF span;
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t j = i + 1; j < points.size(); ++j)
        if (QLineF(points[i], points[j]).length() > longest) {
          longest = QLineF(points[i], points[j]).length();
          span = QLineF(points[i], points[j]);
        }
    if (longest > 0.0) painter->drawLine(span);
  }

  // The centres: a dot and a label, or an arrow towards one at infinity (or too far to draw).
  QFont font = painter->font();
  font.setPointSizeF(canvas::kLabelPointSize * m_scale);
  font.setBold(true);
  painter->setFont(font);
  const double dot = kCentreDotPx * m_scale;
  for (const NamedCentre& n : named(c)) {
    painter->setPen(QPen(colors().centre, 1.5 * m_scale));
    if (near(*n.centre, c)) {
      const QPointF at = px(n.centre->position);
      painter->setBrush(colors().centre);
      painter->drawEllipse(at, dot, dot);
      painter->setBrush(Qt::NoBrush);
      drawLabel(painter, at - QPointF(dot + 2.0, dot + 2.0), n.label);
      continue;
    }
    if (n.centre->kind == k::CentreKind::Indeterminate || !near(*n.anchor, c)) continue;
    const Eigen::Vector2d direction = n.centre->kind == k::CentreKind::AtInfinity
                                          ? n.centre->direction
                                          : Eigen::Vector2d(n.centre->position - n.anchor->position);
    const QPointF from = px(n.anchor->position);
    QPointF unit = px(n.anchor->position + direction) - from;
    const double length = std::hypot(unit.x(), unit.y());
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    unit /= length;
    drawArrow(painter, from, unit, kFarArrowPx * m_scale, 8.0 * m_scale);
    drawLabel(painter, from + unit * (kFarArrowPx + 4.0) * m_scale, n.label + QStringLiteral(" ∞"));
  }
  painter->restore();
}

}  // namespace linkwright::ui
