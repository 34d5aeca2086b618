#pragma once
// Instant centres on the canvas (View ▸ Instant centres): every centre Iij of the linkage at
// the current pose (six for a four-bar, fifteen for a six-bar), labelled, with the two Kennedy
// lines that located each secondary one (three centres of any three bodies lie on one line); a
// centre at infinity, or too far to draw, as an arrow along its direction; a note naming the
// centres Kennedy's theorem does not reach; and the centrodes of the first floating body (a
// coupler) over the cycle: the fixed one in the frame, the moving one carried by the body,
// touching at I1k. Every position comes from the core through the document (centresAtPose(),
// centrodes()); this item only draws, in screen pixels, so marks and text keep their size at any zoom. A linkage
// whose bodies the core cannot find shows nothing and says why (reason()).

#include "ui/document/centres_at_pose.h"

#include "kinematics/analysis/centrodes.h"
#include "kinematics/analysis/instant_centres.h"

#include <QGraphicsItem>
#include <QRectF>
#include <QString>

#include <optional>
#include <vector>

namespace linkwright::ui {

class InstantCentresItem : public QGraphicsItem {
public:
  explicit InstantCentresItem(QGraphicsItem* parent = nullptr);

  /// The centrodes to draw (the document's, derived from its sweep: a Design or Request change).
  void setCentrodes(const kinematics::Centrodes& centrodes);
  /// The centres at the pose, and the coupler's frame that places the moving centrode (the
  /// document's, derived at each pose).
  void setCentres(const CentresAtPose& centres);
  void setPresentationScale(double factor);

  /// What is drawn, for tests: the centres at the pose (none when reason() is set), the
  /// centrodes (moving in the coupler's frame) and the coupler frame they are placed with.
  const std::optional<kinematics::InstantCentres>& centres() const { return m_centres; }
  const kinematics::Centrodes& centrodes() const { return m_centrodes; }
  const std::optional<kinematics::CouplerFrame>& couplerFrame() const { return m_frame; }
  /// Why nothing is drawn: the core's sentence; empty when the centres are shown.
  const QString& reason() const { return m_reason; }
  /// The centres Kennedy's theorem leaves unresolved at this pose, named ("I₁₅, I₃₆ …"); empty
  /// when it resolves every one.
  QString unresolvedNote() const;
  /// The centres' label boxes drawn at the last paint, in that paint's pixels; each is placed
  /// off the canvas's own labels (point names) and the centres' labels before it.
  const std::vector<QRectF>& drawnLabels() const { return m_drawnLabels; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  void updateBounds();

  std::optional<kinematics::InstantCentres> m_centres;
  kinematics::Centrodes m_centrodes;
  std::optional<kinematics::CouplerFrame> m_frame;
  std::vector<QRectF> m_drawnLabels;
  QString m_reason;
  double m_scale = 1.0;
  QRectF m_bounds;
};

}  // namespace linkwright::ui
