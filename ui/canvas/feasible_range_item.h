#pragma once
// Where the crank can turn when it cannot turn through 360°: around O2 at the crank's radius,
// the assemblable directions as a green arc and the rest as a hatched grey sector, with the
// limits written out ("crank can reach 41.4° to 138.6°"). This is how the user sees where,
// and so why, the linkage cannot be assembled. The angles come from the core's InputRange;
// this item only draws arcs for them.

#include "kinematics/analysis/assembly_range.h"

#include <QCoreApplication>
#include <QGraphicsItem>
#include <QPainterPath>

namespace linkwright::ui {

class FeasibleRangeItem : public QGraphicsItem {
  Q_DECLARE_TR_FUNCTIONS(FeasibleRangeItem)
public:
  explicit FeasibleRangeItem(QGraphicsItem* parent = nullptr);

  /// Shows `range` around `centre` (the crank pivot, scene coordinates) at `radius` (the crank
  /// length). Angles in rad, counter-clockwise from +x, as the core gives them; the crank
  /// points at input angle + `phase` (rad, the crank tip's phase).
  void setRange(const kinematics::InputRange& range, const QPointF& centre, double radius, double phase = 0.0);
  void setPresentationScale(double factor);
  /// The sentence that goes with the arc. The scene draws it (LinkageScene), above the links,
  /// so no line of the linkage crosses its text.
  QString labelText() const { return m_labelText; }
  /// Where that sentence goes: beyond the arc's end in the middle of the widest unreachable
  /// sector (scene coordinates), on the side `labelDirection` points to, away from the pivot
  /// and its name.
  QPointF labelAnchor() const { return m_labelAnchor; }
  QPointF labelDirection() const { return m_labelDirection; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  QPainterPath m_feasibleArcs;
  QPainterPath m_infeasibleSectors;
  QPainterPath m_infeasibleArcs;
  QPainterPath m_limitRays;
  QRectF m_bounds;
  double m_scale = 1.0;
  QString m_labelText;
  QPointF m_labelAnchor;
  QPointF m_labelDirection{1.0, 0.0};
};

}  // namespace linkwright::ui
