#pragma once
// The items that draw one mechanism, made from its DrawingPlan: a bar per link (a plate for a
// link carrying points, a slotted bar for an RPR link), a slideway and block per slider, dashed
// frame lines between ground pivots, a support per ground pivot, a pin or dot per point, point
// names, the traced path of each point fixed on a link, the path of each driven point (with the
// stretches the linkage cannot reach), each actuator's cylinder and each two-link workspace. The scene makes a new set when the
// plan changes and otherwise only moves them: setDesign on a design change (paths, the reach
// of slideways and slots over the cycle), setPose on every frame.

#include "ui/canvas/drag_handles.h"
#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep.h"

#include <QColor>
#include <QLineF>
#include <QPointF>
#include <QRectF>

#include <optional>
#include <vector>

class QGraphicsItem;
class QGraphicsLineItem;
class QGraphicsPolygonItem;
class QGraphicsScene;

namespace linkwright::ui {

class ActuatorItem;
class CouplerPathItem;
class DrivenPathItem;
class GroundPivotItem;
class JointHandleItem;
class LabelItem;
class LinkItem;
class SliderBlockItem;
class SlidewayItem;
class SlottedLinkItem;
class WorkspaceItem;

class MechanismItems {
public:
  /// Adds the items for `plan` (of `mechanism`) to `scene`, which owns them. `linkColors`: per
  /// link, the colour to draw it in; a link it does not cover takes linkColor(index).
  MechanismItems(QGraphicsScene* scene, const kinematics::Mechanism& mechanism, DrawingPlan plan,
                 std::vector<QColor> linkColors = {});
  /// Removes and deletes the items.
  ~MechanismItems();
  MechanismItems(const MechanismItems&) = delete;
  MechanismItems& operator=(const MechanismItems&) = delete;

  const DrawingPlan& plan() const { return m_plan; }

  /// Design-level drawing: traced paths and the extents slideways and slots need over the
  /// cycle. `linkageSize` (model units) sets the margins around the travel.
  /// `time`: the design's time base, if it has one, to say when a driven point is where.
  void setDesign(const kinematics::Mechanism& mechanism, const kinematics::SweepResult& sweep,
                 const kinematics::Pose& pose, double linkageSize,
                 const std::optional<kinematics::TimeBase>& time = std::nullopt);
  /// What the design-level drawing adds beyond the points' positions over the cycle: the
  /// slideways' ends and the slotted bars' reach (model units; empty if nothing).
  QRectF extraExtent() const { return m_extraExtent; }
  /// Moves everything to `pose`.
  void setPose(const kinematics::Mechanism& mechanism, const kinematics::Pose& pose);
  void setPresentationScale(double factor);
  /// Highlights one handle (or none).
  void setHot(const std::optional<DragHandle>& handle);

  /// The handle's item: a ground support, a pin or dot, or a path vertex's square; nullptr if
  /// it has none.
  QGraphicsItem* handle(const DragHandle& handle) const;
  LinkItem* link(kinematics::LinkId link) const;
  SlottedLinkItem* slottedLink(kinematics::LinkId link) const;
  QGraphicsPolygonItem* body(kinematics::LinkId link) const;
  CouplerPathItem* path(kinematics::PointId point) const;
  LabelItem* label(kinematics::PointId point) const;
  /// The block (and slideway) of slider `index` in plan().sliders.
  SliderBlockItem* block(std::size_t index) const { return m_blocks[index]; }
  SlidewayItem* slideway(std::size_t index) const { return m_slideways[index]; }
  /// The block a slotted link slides on, for plan().slottedLinks[index].
  SliderBlockItem* slotBlock(std::size_t index) const { return m_slotBlocks[index]; }
  /// The drawn path of plan().drivenPaths[index], the cylinder of plan().actuators[index] and
  /// the annulus of plan().workspaces[index].
  DrivenPathItem* drivenPath(std::size_t index) const { return m_drivenPaths[index]; }
  ActuatorItem* actuator(std::size_t index) const { return m_actuators[index]; }
  WorkspaceItem* workspace(std::size_t index) const { return m_workspaces[index]; }

private:
  QColor colorOf(std::size_t link) const;
  template <typename Item>
  Item* add(Item* item);
  void placeSliders(const kinematics::Mechanism& mechanism, const kinematics::Pose& pose);
  void placeSlots(const kinematics::Pose& pose);
  void placeLabels(const kinematics::Mechanism& mechanism, const kinematics::Pose& pose);
  void setDrivenDesign(const kinematics::Mechanism& mechanism, const kinematics::SweepResult& sweep,
                       const kinematics::Pose& pose, const std::optional<kinematics::TimeBase>& time);
  double barLength(std::size_t slot, double tipDistance) const;  // slotted bar, pivot to far end

  QGraphicsScene* m_scene;
  std::vector<QColor> m_linkColors;
  DrawingPlan m_plan;
  std::vector<QGraphicsItem*> m_owned;
  std::vector<LinkItem*> m_links;                              // per link; null for slotted links
  std::vector<QGraphicsPolygonItem*> m_bodies;                 // per plan body
  std::vector<SlottedLinkItem*> m_slots;                       // per plan slot
  std::vector<SliderBlockItem*> m_slotBlocks;                  // per plan slot
  std::vector<SlidewayItem*> m_slideways;                      // per plan slider
  std::vector<SliderBlockItem*> m_blocks;                      // per plan slider
  std::vector<QGraphicsLineItem*> m_frameLines;                // per plan frame line
  std::vector<LinkItem*> m_constraintBars;                     // per plan constraint bar
  std::vector<GroundPivotItem*> m_grounds;                     // per point; null unless ground
  std::vector<JointHandleItem*> m_joints;                      // per point; null for ground
  std::vector<LabelItem*> m_labels;                            // per point
  std::vector<CouplerPathItem*> m_paths;                       // per point; null unless traced
  std::vector<DrivenPathItem*> m_drivenPaths;                  // per plan driven path
  std::vector<std::vector<JointHandleItem*>> m_vertexHandles;  // per plan driven path, per vertex
  std::vector<ActuatorItem*> m_actuators;                      // per plan actuator
  std::vector<WorkspaceItem*> m_workspaces;                    // per plan workspace
  std::vector<QLineF> m_groundSlideways;                       // per slider: the fixed ends of a ground guide
  std::vector<double> m_slotReach;  // per slot: nearest, farthest distance of the block from the pivot
  double m_margin = 1.0;            // model units around travels
  QRectF m_extraExtent;             // see extraExtent()
};

}  // namespace linkwright::ui
