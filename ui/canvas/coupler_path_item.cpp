#include "ui/canvas/coupler_path_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/geometry.h"

#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>

#include <cmath>

namespace linkwright::ui {
namespace {
// How far (pixels) a sample may lie from the path drawn.
constexpr double kPathTolerancePx = 0.2;
}  // namespace

CouplerPathItem::CouplerPathItem(QGraphicsItem* parent) : QGraphicsPathItem(parent) {
  QPen pen(colors().couplerPoint, canvas::kPathWidthPx, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  setPen(pen);
  setBrush(Qt::NoBrush);
  setZValue(canvas::z::kPath);
}

void CouplerPathItem::setFromSweep(const kinematics::SweepResult& sweep, kinematics::PointId point) {
  m_runs.clear();
  if (point.index < sweep.position.size()) {
    const auto& positions = sweep.position[point.index];
    bool penDown = false;
    for (std::size_t j = 0; j < positions.size() && j < sweep.size(); ++j) {
      if (!sweep.assembled(j)) {
        penDown = false;
        continue;
      }
      if (!penDown) m_runs.append(QList<QPointF>{});
      m_runs.back().append(toQt(positions[j]));
      penDown = true;
    }
  }
  QPainterPath path;
  for (const QList<QPointF>& run : m_runs) path.addPolygon(QPolygonF(run));
  m_drawnScale = 0.0;
  setPath(path);
}

void CouplerPathItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  // Within 5 % of the zoom it was made for, the drawn path stays within 1.05 × the tolerance.
  constexpr double kRemakeRatio = 1.05;
  const double scale = std::sqrt(std::abs(painter->worldTransform().determinant()));
  if (!(m_drawnScale > 0.0 && scale <= kRemakeRatio * m_drawnScale && m_drawnScale <= kRemakeRatio * scale)) {
    m_drawn.clear();
    QList<QPointF> kept;
    for (const QList<QPointF>& run : m_runs) {
      simplifyForScreen(run, {scale, scale}, kPathTolerancePx, kept, m_scratch);
      m_drawn.addPolygon(QPolygonF(kept));
    }
    m_drawnScale = scale;
  }
  painter->setPen(pen());
  painter->setBrush(Qt::NoBrush);
  painter->drawPath(m_drawn);
}

void CouplerPathItem::setPresentationScale(double factor) {
  QPen p = pen();
  p.setWidthF(canvas::kPathWidthPx * factor);
  setPen(p);
}

}  // namespace linkwright::ui
