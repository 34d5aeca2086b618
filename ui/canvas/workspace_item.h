#pragma once
// Where a two-link chain from a ground pivot can put its far end: the annulus between radii
// |l1 − l2| and l1 + l2 about the pivot (a two-link arm's workspace), lightly filled, its two
// circles outlined.

#include <QGraphicsPathItem>

namespace linkwright::ui {

class WorkspaceItem : public QGraphicsPathItem {
public:
  explicit WorkspaceItem(QGraphicsItem* parent = nullptr);

  /// The annulus about `centre` between `inner` and `outer` (scene units; inner may be 0).
  void setAnnulus(const QPointF& centre, double inner, double outer);
  void setPresentationScale(double factor);
};

}  // namespace linkwright::ui
