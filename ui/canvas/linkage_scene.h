#pragma once
// The scene that draws the document's linkage, in model units with y up: the mechanism's
// items (mechanism_items.h: bars, plates, slotted links, slideways and blocks, supports, pins,
// names, traced paths), the crank's feasible range when it cannot turn fully, the rate arrows
// and the message a refused drag shows. It reads the document and nothing else: on a design
// change it rebuilds what depends on the design (items when the structure changed, paths,
// ranges, arrow scales, bounds), on motion it only moves items. LinkageView shows it and turns
// mouse input into edits.

#include "ui/canvas/drag_handles.h"
#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/design/point_drag.h"
#include "kinematics/model/ids.h"

#include <QColor>
#include <QGraphicsScene>

#include <memory>
#include <optional>
#include <vector>

class QGraphicsPolygonItem;

namespace linkwright::ui {

class MassCentresItem;
class SpringsItem;

class ArrowItem;
class CouplerPathItem;
class FeasibleRangeItem;
class InstantCentresItem;
class LabelItem;
class LinkItem;
class MechanismDocument;
class MechanismItems;
class SliderBlockItem;
class SlidewayItem;
class SlottedLinkItem;

class LinkageScene : public QGraphicsScene {
  Q_OBJECT
public:
  explicit LinkageScene(QObject* parent = nullptr);
  ~LinkageScene() override;

  /// Rebuilds everything from `document` (after a Design or Request change).
  void updateDesign(const MechanismDocument& document);
  /// Moves the items to the document's current pose (after a Motion change).
  void updatePose(const MechanismDocument& document);

  void setPresentationScale(double factor);
  /// Takes the current theme's colours (ui/colors.h): the items that keep a colour are made
  /// anew from `document`, the rest are drawn again.
  void refreshColors(const MechanismDocument& document);
  /// Per link (Mechanism::links order), the colour to draw it in: the inversions keep a physical
  /// link's colour whatever link is grounded. Empty (the default): linkColor(index). Takes
  /// effect at the next updateDesign.
  void setLinkColors(std::vector<QColor> colors);
  /// Whether the crank's range is stated in words beside its arc (by default).
  void setRangeLabelShown(bool shown);
  void setShowVelocityArrows(bool show);
  void setShowAccelerationArrows(bool show);
  /// The instant centres, Kennedy's lines and the centrodes (instant_centres_item.h), solved
  /// from `document` now and on every change while shown.
  void setShowInstantCentres(bool show, const MechanismDocument& document);

  /// Where the drawing lies (model units): every point over the cycle, the current pose and
  /// the crank's range arc. Set by updateDesign.
  QRectF contentBounds() const { return m_bounds; }
  /// The larger side of contentBounds(), never zero.
  double linkageSize() const;

  /// The drag handles, in picking order.
  const std::vector<DragHandle>& handles() const { return m_handles; }
  /// Where a handle is drawn now (scene units); nullopt if there is no such handle.
  std::optional<QPointF> handlePosition(const DragHandle& handle) const;
  /// Highlights one handle (or none).
  void setHotHandle(const std::optional<DragHandle>& handle);

  /// A boxed message next to `scenePos` (why a drag was refused), until hideMessage().
  void showMessage(const QPointF& scenePos, const QString& text);
  void hideMessage();

  /// Read access for the view's tests and for export. Null where the item does not exist.
  const DrawingPlan& plan() const;
  const MechanismItems& mechanismItems() const { return *m_items; }
  const QGraphicsItem* handleItem(const DragHandle& handle) const;
  const LinkItem* linkItem(kinematics::LinkId link) const;
  const SlottedLinkItem* slottedLinkItem(kinematics::LinkId link) const;
  const QGraphicsPolygonItem* bodyItem(kinematics::LinkId link) const;
  const QGraphicsPolygonItem* couplerTriangleItem() const;
  const CouplerPathItem* pathItem(kinematics::PointId point) const;
  const LabelItem* pointLabel(kinematics::PointId point) const;
  /// The block and slideway of the slider on `joint` (its first guide for a PRP pin).
  const SliderBlockItem* sliderBlock(kinematics::PointId joint) const;
  const SlidewayItem* slideway(kinematics::PointId joint) const;
  const FeasibleRangeItem* feasibleRangeItem() const { return m_range; }
  const InstantCentresItem* instantCentresItem() const { return m_centres; }
  const SpringsItem* springsItem() const { return m_springs; }
  const MassCentresItem* massCentresItem() const { return m_massCentres; }
  /// Arrows at every moving point; nullptr for ground pivots.
  const ArrowItem* velocityArrow(kinematics::PointId point) const;
  const ArrowItem* accelerationArrow(kinematics::PointId point) const;
  const LabelItem* messageItem() const { return m_message; }
  /// The crank's range in words (feasibleRangeItem's sentence), where the scene draws it.
  const LabelItem* rangeLabelItem() const { return m_rangeLabel; }
  /// Scene units per (length unit/s) and per (length unit/s²); 0 when nothing moves.
  double velocityScale() const { return m_velocityScale; }
  double accelerationScale() const { return m_accelerationScale; }

private:
  void rebuildArrows(std::size_t points);
  void placeRangeLabel();
  void updateArrows(const MechanismDocument& document);
  void computeBounds(const MechanismDocument& document);
  void computeArrowScales(const MechanismDocument& document);
  std::optional<std::size_t> sliderIndex(kinematics::PointId joint) const;

  std::unique_ptr<MechanismItems> m_items;
  std::vector<QColor> m_linkColors;
  bool m_colorsChanged = false;
  std::vector<DragHandle> m_handles;
  FeasibleRangeItem* m_range;
  InstantCentresItem* m_centres;
  SpringsItem* m_springs;
  MassCentresItem* m_massCentres;
  std::vector<ArrowItem*> m_velocityArrows;  // per point; null for ground pivots
  std::vector<ArrowItem*> m_accelerationArrows;
  LabelItem* m_message;
  LabelItem* m_rangeLabel;  ///< m_range's sentence, drawn above the links
  bool m_rangeLabelShown = true;

  QRectF m_bounds;
  bool m_showVelocity = false;
  bool m_showAcceleration = false;
  double m_velocityScale = 0.0;
  double m_accelerationScale = 0.0;
  double m_presentationScale = 1.0;
};

}  // namespace linkwright::ui
