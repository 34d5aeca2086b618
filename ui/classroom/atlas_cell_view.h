#pragma once
// One cell of the atlas window: a small drawing of its coupler curve (the core's samples,
// scaled to fit, y up) with what the classifier found marked on it (cusps red dots, crunodes
// blue rings, the mirror line dashed grey, the straight run thick green, the circular run thick
// orange), its ratios and feature names beneath. Until its cell is computed it says so. A click
// asks for its linkage (clicked); the window loads it.

#include "kinematics/explore/coupler_atlas.h"

#include <QPolygonF>
#include <QStringList>
#include <QWidget>

#include <optional>

namespace linkwright::ui {

class AtlasCellView : public QWidget {
  Q_OBJECT
public:
  AtlasCellView(std::size_t index, const kinematics::AtlasCellKey& key, QWidget* parent = nullptr);

  std::size_t index() const { return m_index; }
  const kinematics::AtlasCellKey& key() const { return m_key; }
  /// Gives the computed cell (its key must be this view's).
  void setCell(const kinematics::AtlasCell& cell);
  const std::optional<kinematics::AtlasCell>& cell() const { return m_cell; }
  /// The curve as drawn, in the cell's own coordinates (crank lengths): the core's samples.
  const QPolygonF& drawnCurve() const { return m_curve; }
  /// The drawn curve's transform from the cell's coordinates to the widget's pixels.
  QTransform modelToWidget() const;
  /// The label under the drawing: ratios, and the features found (or "computing…").
  QString label() const;
  /// label()'s lines as drawn under the curve: each elided ("…") to the cell's width, the
  /// whole text being in the tooltip's description.
  QStringList shownLabel() const;

  QSize sizeHint() const override { return {kSide, kSide}; }
  static constexpr int kSide = 168;

signals:
  void clicked(std::size_t index);

protected:
  void paintEvent(QPaintEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

private:
  QFont labelFont() const;
  void drawFeatures(QPainter& painter, const QTransform& t) const;

  std::size_t m_index;
  kinematics::AtlasCellKey m_key;
  std::optional<kinematics::AtlasCell> m_cell;
  QPolygonF m_curve;
};

/// A sentence of what the cell's curve has, with where (crank angles in degrees, points in
/// crank lengths), for the cell's tooltip.
QString atlasCellDescription(const kinematics::AtlasCell& cell);

}  // namespace linkwright::ui
