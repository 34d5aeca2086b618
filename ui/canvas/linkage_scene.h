#pragma once
// The items that draw a four-bar, in model units with y up: the frame line, the crank's
// feasible range, the coupler path, the coupler triangle, the three links, the ground pivots,
// the joints, the rate arrows and their labels. It reads the document and nothing else: on a
// design change it rebuilds what depends on the design (path, range, arrow scales, bounds),
// on motion it only moves items. LinkageView shows it and turns mouse input into edits.

#include "kinematics/model/design_edit.h"
#include "kinematics/model/ids.h"

#include <QGraphicsScene>

#include <array>
#include <optional>

class QGraphicsLineItem;
class QGraphicsPolygonItem;

namespace linkwright::ui {

class ArrowItem;
class CouplerPathItem;
class FeasibleRangeItem;
class GroundPivotItem;
class JointHandleItem;
class LabelItem;
class LinkItem;
class MechanismDocument;

class LinkageScene : public QGraphicsScene {
  Q_OBJECT
public:
  explicit LinkageScene(QObject* parent = nullptr);

  /// Rebuilds everything from `document` (after a Design or Request change).
  void updateDesign(const MechanismDocument& document);
  /// Moves the items to the document's current pose (after a Motion change).
  void updatePose(const MechanismDocument& document);

  void setPresentationScale(double factor);
  void setShowVelocityArrows(bool show);
  void setShowAccelerationArrows(bool show);

  /// Where the drawing lies (model units): every point over the cycle, the current pose and
  /// the crank's range arc. Set by updateDesign.
  QRectF contentBounds() const { return m_bounds; }
  /// The larger side of contentBounds(), never zero.
  double linkageSize() const;

  /// Where `handle` is drawn now (scene units); nullopt for P when there is no coupler point.
  std::optional<QPointF> handlePosition(kinematics::FourBarHandle handle) const;
  /// Highlights one handle (or none).
  void setHotHandle(std::optional<kinematics::FourBarHandle> handle);

  /// A boxed message next to `scenePos` (why a drag was refused), until hideMessage().
  void showMessage(const QPointF& scenePos, const QString& text);
  void hideMessage();

  /// Read access for the view's tests and for export.
  const QGraphicsItem* handleItem(kinematics::FourBarHandle handle) const;
  const LinkItem* linkItem(kinematics::LinkId link) const;
  const FeasibleRangeItem* feasibleRangeItem() const { return m_range; }
  const CouplerPathItem* couplerPathItem() const { return m_path; }
  const QGraphicsPolygonItem* couplerTriangleItem() const { return m_couplerTriangle; }
  /// Arrows at B, C and P; nullptr for other points.
  const ArrowItem* velocityArrow(kinematics::PointId point) const;
  const ArrowItem* accelerationArrow(kinematics::PointId point) const;
  const LabelItem* messageItem() const { return m_message; }
  /// Scene units per (length unit/s) and per (length unit/s²); 0 when nothing moves.
  double velocityScale() const { return m_velocityScale; }
  double accelerationScale() const { return m_accelerationScale; }

private:
  static constexpr std::size_t kArrowPoints = 3;  // B, C, P
  void updateArrows(const MechanismDocument& document);
  void computeBounds(const MechanismDocument& document);
  void computeArrowScales(const MechanismDocument& document);
  static int arrowSlot(kinematics::PointId point);

  QGraphicsLineItem* m_frame;
  FeasibleRangeItem* m_range;
  CouplerPathItem* m_path;
  QGraphicsPolygonItem* m_couplerTriangle;
  LinkItem* m_crank;
  LinkItem* m_coupler;
  LinkItem* m_rocker;
  GroundPivotItem* m_groundO2;
  GroundPivotItem* m_groundO4;
  JointHandleItem* m_pinB;
  JointHandleItem* m_pinC;
  JointHandleItem* m_dotP;
  std::array<LabelItem*, 5> m_pointLabels{};  // O2, O4, B, C, P
  std::array<ArrowItem*, kArrowPoints> m_velocityArrows{};
  std::array<ArrowItem*, kArrowPoints> m_accelerationArrows{};
  LabelItem* m_message;

  QRectF m_bounds;
  bool m_hasCouplerPoint = false;
  bool m_showVelocity = false;
  bool m_showAcceleration = false;
  double m_velocityScale = 0.0;
  double m_accelerationScale = 0.0;
  double m_presentationScale = 1.0;
};

} // namespace linkwright::ui
