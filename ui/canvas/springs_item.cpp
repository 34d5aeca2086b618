#include "ui/canvas/springs_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/colors.h"

#include <QLineF>
#include <QPainterPath>
#include <QPen>

#include <cmath>

namespace linkwright::ui {

namespace {
constexpr int kCoils = 8;
constexpr double kSpringWidthPx = 1.5;
}  // namespace

std::vector<QPointF> springPolyline(const QPointF& a, const QPointF& b, double width) {
  const QLineF line(a, b);
  if (line.length() == 0.0) return {a, b};
  const QPointF along = (b - a) / line.length();
  const QPointF across(-along.y(), along.x());
  const QPointF start = a + (b - a) / 6.0, end = b - (b - a) / 6.0;
  std::vector<QPointF> points{a, start};
  for (int k = 0; k < 2 * kCoils; ++k) {
    const double t = (k + 0.5) / (2.0 * kCoils);
    points.push_back(start + t * (end - start) + (k % 2 == 0 ? 0.5 : -0.5) * width * across);
  }
  points.push_back(end);
  points.push_back(b);
  return points;
}

SpringsItem::SpringsItem(QGraphicsItem* parent) : QGraphicsPathItem(parent) {
  setZValue(canvas::z::kLinks - 0.5);
  setPresentationScale(1.0);
}

void SpringsItem::setSprings(const kinematics::Mechanism& m, const std::vector<kinematics::Spring>& springs,
                             double width) {
  m_ends.clear();
  for (const kinematics::Spring& s : springs) {
    const auto a = m.findPoint(s.first.point), b = m.findPoint(s.second.point);
    if (a && b) m_ends.emplace_back(*a, *b);
  }
  m_width = width;
  setVisible(!m_ends.empty());
}

void SpringsItem::setPose(const kinematics::Pose& pose) {
  QPainterPath path;
  for (const auto& [a, b] : m_ends) {
    if (a.index >= pose.position.size() || b.index >= pose.position.size()) continue;
    const auto& p = pose.position[a.index];
    const auto& q = pose.position[b.index];
    const std::vector<QPointF> points = springPolyline(QPointF(p.x(), p.y()), QPointF(q.x(), q.y()), m_width);
    path.moveTo(points.front());
    for (std::size_t i = 1; i < points.size(); ++i) path.lineTo(points[i]);
  }
  setPath(path);
}

void SpringsItem::setPresentationScale(double factor) {
  QPen pen(colors().frame, kSpringWidthPx * factor);
  pen.setCosmetic(true);
  pen.setJoinStyle(Qt::RoundJoin);
  setPen(pen);
}

}  // namespace linkwright::ui
