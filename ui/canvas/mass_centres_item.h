#pragma once
// The links' centres of mass (kinematics::LinkMass) drawn at the current pose: a circle
// crossed by the edges of two opposite quarters, and a thin arm from the link's first joint
// when the centre lies off the line between its joints (a counterweight behind a pivot, a bent
// link). Its size is a fixed share of the linkage's, so it reads at any zoom.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/ids.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <QGraphicsPathItem>

#include <vector>

namespace linkwright::ui {

class MassCentresItem : public QGraphicsPathItem {
public:
  explicit MassCentresItem(QGraphicsItem* parent = nullptr);

  /// The masses to draw (those above 0 on a link of `mechanism`), `radius` scene units each.
  void setMasses(const kinematics::Mechanism& mechanism, const std::vector<kinematics::LinkMass>& masses,
                 double radius);
  /// Redraws them at `pose`'s positions.
  void setPose(const kinematics::Pose& pose);
  void setPresentationScale(double factor);

  /// Where each mass's centre was drawn at the last pose (scene units), in the masses' order.
  const std::vector<QPointF>& centres() const { return m_centres; }

private:
  struct Drawn {
    kinematics::LinkMass mass;
    kinematics::PointId first, second;
  };
  std::vector<Drawn> m_masses;
  std::vector<QPointF> m_centres;
  double m_radius = 1.0;
};

}  // namespace linkwright::ui
