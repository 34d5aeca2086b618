#pragma once
// The chosen synthesis candidate on the canvas: its linkage dashed at its pose at the first
// target (solved by the core's pose solver), over the document's own linkage, and the targets:
// points as crosses, coupler poses as a dot with a short arrow along the coupler's angle.
// Marks keep their pixel size at any zoom. The panel adds it to the canvas's scene and hides
// it while the Synthesis tab is not shown or no candidate is chosen.

#include "ui/synthesis/synthesis_outcome.h"

#include "kinematics/model/mechanism.h"

#include <QGraphicsItem>
#include <QLineF>
#include <QString>

#include <optional>

#include <vector>

namespace linkwright::ui {

class SynthesisPreviewItem : public QGraphicsItem {
public:
  explicit SynthesisPreviewItem(QGraphicsItem* parent = nullptr);

  /// Draws `mechanism` at input `input` (rad), with `targets`. Returns the reason if the pose
  /// cannot be solved: then only the targets are drawn.
  std::optional<QString> setPreview(const kinematics::Mechanism& mechanism, double input, const PreviewMarks& targets);
  /// Draws nothing.
  void clear();

  /// What is drawn (scene units), for tests: the links as segments, the pivots, the targets.
  const std::vector<QLineF>& links() const { return m_links; }
  const std::vector<QPointF>& pivots() const { return m_pivots; }
  const PreviewMarks& targets() const { return m_targets; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  std::vector<QLineF> m_links;
  std::vector<QPointF> m_pivots;  // ground pivots
  std::vector<QPointF> m_joints;  // moving joints
  PreviewMarks m_targets;
  QRectF m_bounds;
};

}  // namespace linkwright::ui
