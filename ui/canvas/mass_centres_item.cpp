#include "ui/canvas/mass_centres_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/colors.h"

#include <QBrush>
#include <QPainterPath>
#include <QPen>

#include <cmath>

namespace linkwright::ui {

namespace {
constexpr double kOutlinePx = 1.2;
}  // namespace

MassCentresItem::MassCentresItem(QGraphicsItem* parent) : QGraphicsPathItem(parent) {
  setZValue(canvas::z::kPins + 0.5);  // above the links and pins it sits on
  setPresentationScale(1.0);
}

void MassCentresItem::setMasses(const kinematics::Mechanism& m, const std::vector<kinematics::LinkMass>& masses,
                                double radius) {
  m_masses.clear();
  for (const kinematics::LinkMass& mass : masses) {
    const auto link = m.findLink(mass.link);
    if (!link || !(mass.mass > 0.0)) continue;
    m_masses.push_back({mass, m.links[link->index].first, m.links[link->index].second});
  }
  m_radius = radius;
  setVisible(!m_masses.empty());
}

void MassCentresItem::setPose(const kinematics::Pose& pose) {
  QPainterPath path;
  path.setFillRule(Qt::WindingFill);
  m_centres.clear();
  for (const Drawn& d : m_masses) {
    if (d.first.index >= pose.position.size() || d.second.index >= pose.position.size()) continue;
    const Eigen::Vector2d& a = pose.position[d.first.index];
    const Eigen::Vector2d& b = pose.position[d.second.index];
    const Eigen::Vector2d c = kinematics::massCentreAt(d.mass, a, b);
    const QPointF centre(c.x(), c.y());
    m_centres.push_back(centre);
    // Off the segment between the joints: the arm that carries it.
    const Eigen::Vector2d e = b - a;
    const double t = e.squaredNorm() > 0.0 ? (c - a).dot(e) / e.squaredNorm() : 0.0;
    const double off = e.squaredNorm() > 0.0 ? std::abs(e.x() * (c - a).y() - e.y() * (c - a).x()) / e.norm() : 0.0;
    if (t < 0.0 || t > 1.0 || off > 0.5 * m_radius) {
      path.moveTo(a.x(), a.y());
      path.lineTo(centre);
    }
    const QRectF box(centre.x() - m_radius, centre.y() - m_radius, 2.0 * m_radius, 2.0 * m_radius);
    path.addEllipse(box);
    // Two opposite quarters outlined: the centre-of-mass mark.
    for (const double start : {0.0, 180.0}) {
      path.moveTo(centre);
      path.arcTo(box, start, 90.0);
      path.closeSubpath();
    }
  }
  setPath(path);
}

void MassCentresItem::setPresentationScale(double factor) {
  QPen pen(colors().frame, kOutlinePx * factor);
  pen.setCosmetic(true);
  setPen(pen);
  setBrush(Qt::NoBrush);
}

}  // namespace linkwright::ui
