#pragma once
// The path a driven point is moved along (a tool's line, a piston's bore): the path itself as a
// dash-dotted guide in the frame's colour, and the stretches of it the linkage cannot reach
// (outside a two-link arm's workspace, say) over it in red, each labelled with when the driver
// is there ("outside 0.100–0.200 s") or, without a time base, where ("outside s 0.2–0.4 m").

#include "kinematics/model/mechanism.h"

#include <QGraphicsPathItem>
#include <QString>

#include <utility>
#include <vector>

class QGraphicsSimpleTextItem;

namespace linkwright::ui {

class DrivenPathItem : public QGraphicsPathItem {
public:
  explicit DrivenPathItem(QGraphicsItem* parent = nullptr);

  /// One stretch the driven point cannot reach: its ends as path coordinates and its label.
  struct Stretch {
    double from = 0.0;
    double to = 0.0;
    QString label;
  };

  /// Draws `shape` and the stretches of it in `unreachable`.
  void setShape(const kinematics::PathShape& shape, const std::vector<Stretch>& unreachable);
  /// How many unreachable stretches are drawn, and their labels (for tests).
  std::vector<QString> stretchLabels() const;
  void setPresentationScale(double factor);

private:
  void applyPens();

  double m_scale = 1.0;
  QGraphicsPathItem* m_unreachable;
  std::vector<QGraphicsSimpleTextItem*> m_labels;
};

/// The drawn curve of a path between its coordinates `from` and `to`, in scene units: the
/// polyline's vertices or an arc, finely enough to look round.
QPainterPath pathCurve(const kinematics::PathShape& shape, double from, double to);

}  // namespace linkwright::ui
