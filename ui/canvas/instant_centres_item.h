#pragma once
// Instant centres on the canvas (View ▸ Instant centres): the six centres I₁₂…I₃₄ of a four-bar
// or a slider-crank at the current pose, labelled, with the four Kennedy lines that locate
// I₁₃ and I₂₄ (three centres of any three bodies lie on one line); a centre at infinity, or
// too far to draw, as an arrow along its direction; and the coupler's centrodes over the cycle:
// the fixed one in the frame, the moving one carried by the coupler, touching at I₁₃. Every
// position comes from the core (instant_centres.h, centrodes.h); this item only draws, in
// screen pixels, so marks and text keep their size at any zoom. A linkage whose centres the
// core does not locate shows nothing and says why (reason()).

#include "kinematics/analysis/centrodes.h"
#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep.h"

#include <QGraphicsItem>
#include <QString>

#include <optional>

namespace linkwright::ui {

class InstantCentresItem : public QGraphicsItem {
public:
  explicit InstantCentresItem(QGraphicsItem* parent = nullptr);

  /// The centrodes of `mechanism` over `sweep` (a Design or Request change).
  void setCycle(const kinematics::Mechanism& mechanism, const kinematics::SweepResult& sweep);
  /// The centres at `pose`, and the moving centrode placed with the coupler there.
  void setPose(const kinematics::Mechanism& mechanism, const kinematics::Pose& pose);
  void setPresentationScale(double factor);

  /// What is drawn, for tests: the centres at the pose (none when reason() is set), the
  /// centrodes (moving in the coupler's frame) and the coupler frame they are placed with.
  const std::optional<kinematics::InstantCentres>& centres() const { return m_centres; }
  const kinematics::Centrodes& centrodes() const { return m_centrodes; }
  const std::optional<kinematics::CouplerFrame>& couplerFrame() const { return m_frame; }
  /// Why nothing is drawn: the core's sentence; empty when the centres are shown.
  const QString& reason() const { return m_reason; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  void updateBounds();

  std::optional<kinematics::InstantCentres> m_centres;
  kinematics::Centrodes m_centrodes;
  std::optional<kinematics::CouplerFrame> m_frame;
  QString m_reason;
  double m_scale = 1.0;
  QRectF m_bounds;
};

}  // namespace linkwright::ui
