#include "ui/canvas/coupler_path_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/geometry.h"

#include <QPainterPath>
#include <QPen>

namespace linkwright::ui {

CouplerPathItem::CouplerPathItem(QGraphicsItem* parent) : QGraphicsPathItem(parent) {
  QPen pen(kCouplerPointColor, canvas::kPathWidthPx, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  setPen(pen);
  setBrush(Qt::NoBrush);
  setZValue(canvas::z::kPath);
}

void CouplerPathItem::setFromSweep(const kinematics::SweepResult& sweep, kinematics::PointId point) {
  QPainterPath path;
  if (point.index < sweep.position.size()) {
    const auto& positions = sweep.position[point.index];
    bool penDown = false;
    for (std::size_t j = 0; j < positions.size() && j < sweep.size(); ++j) {
      if (!sweep.assembled(j)) {
        penDown = false;
        continue;
      }
      if (penDown) path.lineTo(toQt(positions[j]));
      else path.moveTo(toQt(positions[j]));
      penDown = true;
    }
  }
  setPath(path);
}

void CouplerPathItem::setPresentationScale(double factor) {
  QPen p = pen();
  p.setWidthF(canvas::kPathWidthPx * factor);
  setPen(p);
}

}  // namespace linkwright::ui
