#pragma once
// Force arrows on the canvas: at every joint, the reaction force at the current crank angle
// (a pin: the force on the joint's body from its hub; a slider: the guide's normal force on
// the block), labelled with its magnitude in N. Arrows are drawn in screen pixels: the largest
// joint force over the cycle is kForceArrowLengthPx long at any zoom, the others in proportion,
// so the arrows compare across the cycle. The caller adds the item to the scene, toggles it
// with setVisible and calls setForces when the ForceResults change.

#include <QColor>
#include <QGraphicsItem>
#include <QSizeF>
#include <QString>
#include <QTransform>

#include <vector>

namespace linkwright::ui {

class ForceResults;
class LabelItem;
class MechanismDocument;

/// Colour of the force arrows and their labels.
inline constexpr QColor kForceArrowColor{178, 34, 34};
/// On-screen length of the largest joint force of the cycle, px at presentation scale 1.
inline constexpr double kForceArrowLengthPx = 120.0;
/// The most of the canvas's smaller side the largest arrow may take.
inline constexpr double kForceArrowCanvasShare = 0.3;

/// One arrow: at a scene point, `lengthPx` screen pixels long in the direction of a vector
/// given in scene axes (y up). Ignores the view's transformations, so it keeps its pixel size.
class ForceArrowItem : public QGraphicsItem {
public:
  explicit ForceArrowItem(QGraphicsItem* parent = nullptr);

  /// At `scenePoint` (scene units), along `direction` (scene axes, any length > 0), `lengthPx`
  /// pixels long, labelled `label` at its tip.
  void setArrow(const QPointF& scenePoint, const QPointF& direction, double lengthPx, const QString& label);
  void setPresentationScale(double factor);

  /// Moves the label from the arrow's tip by `alongPx` out along the arrow and `acrossPx` to
  /// its left (pixels at presentation scale 1).
  void setLabelShift(double alongPx, double acrossPx);
  /// The label's text box in the pixels `sceneToPixels` maps the scene to.
  QRectF labelRect(const QTransform& sceneToPixels) const;
  const LabelItem* labelItem() const { return m_label; }

  double lengthPx() const { return m_lengthPx; }
  /// Unit direction in scene axes (y up).
  QPointF direction() const { return m_direction; }
  QString label() const;

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  QPointF tipPx() const;  // item pixels, y down

  QPointF m_direction{1.0, 0.0};
  double m_lengthPx = 0.0;
  double m_scale = 1.0;
  QPointF m_labelShift;  // along, across the arrow: px at presentation scale 1
  LabelItem* m_label;
};

/// The arrows of every joint; draws nothing itself.
class ForceArrowsItem : public QGraphicsItem {
public:
  explicit ForceArrowsItem(QGraphicsItem* parent = nullptr);

  /// Places one arrow per joint from `forces`' pose forces at `document`'s pose; no arrows
  /// while `forces` has none (disabled, no dynamics, a singular pose).
  void setForces(const MechanismDocument& document, const ForceResults& forces);
  void setPresentationScale(double factor);
  /// The canvas's scale (pixels per scene unit), which sets how near the arrows' feet are on
  /// screen: their labels are kept apart at it, and off the scene's other labels (the points'
  /// names); 0: not known, labels where they fall.
  void setViewScale(double pixelsPerUnit);
  /// The canvas's size in pixels: the largest arrow is at most kForceArrowCanvasShare of its
  /// smaller side, so that the arrows and their labels fit a projector's small canvas in
  /// presentation mode (twice kForceArrowLengthPx, 240 px, in a canvas 378 px tall). Taken at
  /// the next setForces; empty: no bound.
  void setCanvasSize(const QSizeF& pixels);

  /// Whether any arrow is drawn (the item shown, and forces to show).
  bool showsArrows() const;
  /// The arrows, revolute joints first, then prismatic ones; hidden ones are not solved.
  const std::vector<ForceArrowItem*>& arrows() const { return m_arrows; }

  QRectF boundingRect() const override { return {}; }
  void paint(QPainter*, const QStyleOptionGraphicsItem*, QWidget*) override {}

private:
  ForceArrowItem* arrowAt(std::size_t index);
  void separateLabels();

  std::vector<ForceArrowItem*> m_arrows;
  double m_scale = 1.0;
  double m_pixelsPerUnit = 0.0;
  QSizeF m_canvas;
};

}  // namespace linkwright::ui
