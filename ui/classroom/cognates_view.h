#pragma once
// The three four-bars of a coupler curve drawn together (View ▸ Cognates…): the curve the
// coupler point traces, and at the current pose the original and its two Roberts–Chebyshev
// cognates (kinematics/explore/cognates.h), each in its own colour, their ground pivots marked,
// the one coupler point they share ringed. A plain painted widget: it is told the joints and the
// curve, fits them to its size, keeps x right and y up, and computes nothing.

#include "kinematics/explore/cognates.h"

#include <QColor>
#include <QPolygonF>
#include <QWidget>

#include <array>
#include <optional>

namespace linkwright::ui {

class CognatesView : public QWidget {
  Q_OBJECT
public:
  explicit CognatesView(QWidget* parent = nullptr);

  /// The curve (length unit) and the frame of the drawing: every pose shown later fits in it.
  void setCurve(const QPolygonF& curve, const QRectF& extent);
  /// The three four-bars at one pose (original first), or none to draw only the curve.
  void setJoints(const std::optional<std::array<kinematics::FourBarJoints, 3>>& joints);
  const std::optional<std::array<kinematics::FourBarJoints, 3>>& joints() const { return m_joints; }
  const QPolygonF& curve() const { return m_curve; }
  /// The frame the drawing fits; empty when there is nothing to draw.
  const QRectF& extent() const { return m_extent; }

  /// The colour each of the three is drawn in.
  static QColor colorOf(int fourBar);

protected:
  void paintEvent(QPaintEvent* event) override;

private:
  QPolygonF m_curve;
  QRectF m_extent;
  std::optional<std::array<kinematics::FourBarJoints, 3>> m_joints;
};

}  // namespace linkwright::ui
