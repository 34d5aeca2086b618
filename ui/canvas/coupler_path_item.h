#pragma once
// The path a point traces over the analysed cycle, taken from the sweep's positions. Samples
// that could not be assembled break the curve, so no line crosses a gap in the motion. It is
// drawn through only the vertices the view's zoom can show (ui/screen_simplify.h), made again
// when the zoom changes; its shape and bounds are the whole path's.

#include "ui/screen_simplify.h"

#include "kinematics/model/ids.h"
#include "kinematics/solve/sweep.h"

#include <QGraphicsPathItem>
#include <QList>
#include <QPainterPath>
#include <QPointF>

namespace linkwright::ui {

class CouplerPathItem : public QGraphicsPathItem {
public:
  explicit CouplerPathItem(QGraphicsItem* parent = nullptr);

  /// Rebuilds the curve from `sweep`'s positions of `point` (an empty path if it has none).
  void setFromSweep(const kinematics::SweepResult& sweep, kinematics::PointId point);
  void setPresentationScale(double factor);
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  QList<QList<QPointF>> m_runs;  // the assembled stretches of the path, scene units
  QPainterPath m_drawn;          // m_runs simplified for m_drawnScale
  double m_drawnScale = 0.0;     // pixels per scene unit m_drawn was made for (0: none yet)
  SimplifyScratch m_scratch;
};

}  // namespace linkwright::ui
