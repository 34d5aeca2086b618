#include "ui/synthesis/synthesis_preview_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/geometry.h"

#include "kinematics/solve/pose_solver.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr QColor kPreviewColor{90, 60, 200};
constexpr QColor kTargetColor{30, 30, 30};
constexpr double kPreviewWidthPx = 2.5;
constexpr double kCrossPx = 6.0;       // half the cross's size
constexpr double kPoseArrowPx = 36.0;  // a pose's direction arrow
constexpr double kPoseHeadPx = 8.0;
constexpr double kJointPx = 3.5;
constexpr double kPivotPx = 6.0;
constexpr double kBoundsMargin = 0.15;  // of the drawing's size, for the pixel-sized marks

QPen cosmetic(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(color, width, style, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  return pen;
}

}  // namespace

SynthesisPreviewItem::SynthesisPreviewItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
  setZValue(canvas::z::kArrows - 0.5);  // over the document's linkage, under arrows and labels
  setAcceptedMouseButtons(Qt::NoButton);
}

std::optional<QString> SynthesisPreviewItem::setPreview(const k::Mechanism& mechanism, double input,
                                                        const PreviewMarks& targets) {
  prepareGeometryChange();
  m_links.clear();
  m_pivots.clear();
  m_joints.clear();
  m_targets = targets;
  std::optional<QString> why;
  if (mechanism.points.empty()) {
    // Targets only (typed before a search).
  } else if (const auto pose = k::solvePose(mechanism, {input, 0.0, 0.0}, {false, false})) {
    const auto at = [&](k::PointId p) { return toQt(pose->position[p.index]); };
    for (const k::Link& link : mechanism.links) m_links.emplace_back(at(link.first), at(link.second));
    for (std::size_t i = 0; i < mechanism.points.size(); ++i) {
      const k::PointDefinition& d = mechanism.points[i].definition;
      const QPointF p = toQt(pose->position[i]);
      if (std::holds_alternative<k::GroundPoint>(d)) m_pivots.push_back(p);
      else m_joints.push_back(p);
      // A point on a link is drawn as part of its plate: joined to the link's two ends.
      if (const auto* on = std::get_if<k::AttachedPoint>(&d); on && on->link.index < mechanism.links.size()) {
        const k::Link& link = mechanism.links[on->link.index];
        m_links.emplace_back(at(link.first), p);
        m_links.emplace_back(at(link.second), p);
      }
    }
  } else {
    why = QString::fromStdString(pose.error().message);
  }
  bool any = false;
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  const auto grow = [&](const QPointF& p) {
    left = any ? std::min(left, p.x()) : p.x();
    right = any ? std::max(right, p.x()) : p.x();
    bottom = any ? std::min(bottom, p.y()) : p.y();
    top = any ? std::max(top, p.y()) : p.y();
    any = true;
  };
  for (const QLineF& l : m_links) {
    grow(l.p1());
    grow(l.p2());
  }
  for (const QPointF& p : m_pivots) grow(p);
  for (const Eigen::Vector2d& p : m_targets.points) grow(toQt(p));
  for (const k::CouplerPose& p : m_targets.poses) grow(toQt(p.point));
  const QRectF bounds(QPointF(left, bottom), QPointF(right, top));
  const double size = std::max({bounds.width(), bounds.height(), 1e-9});
  m_bounds = bounds.adjusted(-kBoundsMargin * size, -kBoundsMargin * size, kBoundsMargin * size, kBoundsMargin * size);
  update();
  return why;
}

void SynthesisPreviewItem::clear() {
  prepareGeometryChange();
  m_links.clear();
  m_pivots.clear();
  m_joints.clear();
  m_targets = {};
  m_bounds = {};
  update();
}

QRectF SynthesisPreviewItem::boundingRect() const { return m_bounds; }

void SynthesisPreviewItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  // Scene units per screen pixel: marks are sized in pixels.
  const double lod = QStyleOptionGraphicsItem::levelOfDetailFromTransform(painter->worldTransform());
  if (!(lod > 0.0) || !std::isfinite(lod)) return;
  const double px = 1.0 / lod;
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setBrush(Qt::NoBrush);
  painter->setPen(cosmetic(kPreviewColor, kPreviewWidthPx, Qt::DashLine));
  for (const QLineF& l : m_links) painter->drawLine(l);
  painter->setPen(cosmetic(kPreviewColor, 1.5));
  painter->setBrush(Qt::white);
  for (const QPointF& p : m_joints) painter->drawEllipse(p, kJointPx * px, kJointPx * px);
  for (const QPointF& p : m_pivots) {
    const QPointF tri[] = {p, p + QPointF(-kPivotPx, -1.6 * kPivotPx) * px,
                           p + QPointF(kPivotPx, -1.6 * kPivotPx) * px};
    painter->drawPolygon(tri, 3);
    painter->drawEllipse(p, kJointPx * px, kJointPx * px);
  }
  painter->setPen(cosmetic(kTargetColor, 1.5));
  painter->setBrush(Qt::NoBrush);
  for (const Eigen::Vector2d& t : m_targets.points) {
    const QPointF p = toQt(t);
    painter->drawLine(p + QPointF(-kCrossPx, -kCrossPx) * px, p + QPointF(kCrossPx, kCrossPx) * px);
    painter->drawLine(p + QPointF(-kCrossPx, kCrossPx) * px, p + QPointF(kCrossPx, -kCrossPx) * px);
  }
  painter->setBrush(kTargetColor);
  for (const k::CouplerPose& pose : m_targets.poses) {
    // The arrow along the pose's angle: a view transform of a given direction, not geometry.
    const QPointF p = toQt(pose.point);
    const QPointF u(std::cos(pose.angle), std::sin(pose.angle));
    const QPointF n(-u.y(), u.x());
    const QPointF tip = p + kPoseArrowPx * px * u;
    const QPointF base = tip - kPoseHeadPx * px * u;
    painter->drawEllipse(p, kJointPx * px, kJointPx * px);
    painter->drawLine(p, base);
    const QPointF head[] = {tip, base + 0.45 * kPoseHeadPx * px * n, base - 0.45 * kPoseHeadPx * px * n};
    painter->drawPolygon(head, 3);
  }
}

}  // namespace linkwright::ui
