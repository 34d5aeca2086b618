#pragma once
// The design's springs (kinematics::Spring, among its loads) drawn between their ends at the
// current pose: a short straight lead at each end and a zigzag of coils between, their width a
// fixed share of the linkage's size, so a spring reads as one at any zoom and length.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/ids.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <QGraphicsPathItem>

#include <utility>
#include <vector>

namespace linkwright::ui {

class SpringsItem : public QGraphicsPathItem {
public:
  explicit SpringsItem(QGraphicsItem* parent = nullptr);

  /// The springs to draw, resolved to their end points in `mechanism`; the coils are `width`
  /// scene units wide.
  void setSprings(const kinematics::Mechanism& mechanism, const std::vector<kinematics::Spring>& springs, double width);
  /// Redraws the springs at `pose`'s positions.
  void setPose(const kinematics::Pose& pose);
  void setPresentationScale(double factor);

  /// The springs drawn, as their end points' ids.
  const std::vector<std::pair<kinematics::PointId, kinematics::PointId>>& ends() const { return m_ends; }

private:
  std::vector<std::pair<kinematics::PointId, kinematics::PointId>> m_ends;
  double m_width = 1.0;
};

/// The polyline of one spring from `a` to `b`: leads of a sixth of its length at each end and
/// eight coils of `width` between (a straight line when the ends meet).
std::vector<QPointF> springPolyline(const QPointF& a, const QPointF& b, double width);

}  // namespace linkwright::ui
