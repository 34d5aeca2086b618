#pragma once
// The path a point traces over the analysed cycle, taken from the sweep's positions. Samples
// that could not be assembled break the curve, so no line crosses a gap in the motion.

#include "kinematics/model/ids.h"
#include "kinematics/solve/sweep.h"

#include <QGraphicsPathItem>

namespace linkwright::ui {

class CouplerPathItem : public QGraphicsPathItem {
public:
  explicit CouplerPathItem(QGraphicsItem* parent = nullptr);

  /// Rebuilds the curve from `sweep`'s positions of `point` (an empty path if it has none).
  void setFromSweep(const kinematics::SweepResult& sweep, kinematics::PointId point);
  void setPresentationScale(double factor);
};

}  // namespace linkwright::ui
