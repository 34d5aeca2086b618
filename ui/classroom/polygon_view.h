#pragma once
// One velocity or acceleration polygon drawn to scale (kinematics/analysis/vector_polygon.h):
// the arrows tip to tail from the pole o, coloured by kind (absolute, relative, normal,
// tangential, sliding, Coriolis) and labelled, the image points marked, a scale bar and a
// legend. It draws what the core computed and nothing else: positions in the polygon plane
// are divided by the scale (units per cm) and turned into pixels at the screen's resolution.
// "Step" drawing shows only the arrows up to a step, in the order a student draws them.

#include "kinematics/analysis/vector_polygon.h"

#include <QLineF>
#include <QRectF>
#include <QWidget>

#include <climits>
#include <vector>

namespace linkwright::ui {

/// Colour of a polygon arrow of kind `term`.
QColor polygonTermColor(kinematics::VectorTerm term);
/// "absolute", "relative", "normal", "tangential", "sliding", "Coriolis".
QString polygonTermName(kinematics::VectorTerm term);

/// Where the labels of a drawing went, so that the next one goes where it hides nothing.
struct LabelLayout {
  QRectF bounds;              ///< labels stay inside (the widget)
  std::vector<QRectF> boxes;  ///< labels and image dots placed so far
  std::vector<QLineF> lines;  ///< the arrows
  /// How much `box` hides: 100 a label or dot it overlaps, 1 a sample of a line under it,
  /// 1e6 if it leaves the bounds; 0 when it hides nothing.
  double cost(const QRectF& box) const;
  /// The first candidate that hides nothing, else the one that hides least, recorded as taken.
  QRectF place(const std::vector<QRectF>& candidates);
};

class PolygonView : public QWidget {
  Q_OBJECT
public:
  explicit PolygonView(QWidget* parent = nullptr);

  static constexpr int kAllSteps = INT_MAX;

  /// Draws `polygon` (a copy is kept); the step and the chosen scale stay as they were.
  void setPolygon(const kinematics::VectorPolygon& polygon);
  const kinematics::VectorPolygon& polygon() const { return m_polygon; }

  /// Polygon units per cm of drawing; 0 (the default) fits the polygon to the widget at a
  /// round scale.
  void setChosenScale(double unitsPerCm);
  double chosenScale() const { return m_chosenScale; }
  /// The scale drawn with: the chosen one, or the round scale that fits.
  double scale() const;
  /// The round scale at which the whole polygon fits the widget.
  double fitScale() const;
  /// Pixels per cm of drawing (the screen's logical resolution).
  double pixelsPerCm() const;

  /// Arrows with a step up to `step` are drawn (0: none, kAllSteps: all).
  void setRevealedStep(int step);
  int revealedStep() const { return m_revealed; }
  /// The arrows drawn now, in the polygon plane, in step order.
  std::vector<kinematics::PolygonVector> drawnVectors() const;
  /// The images marked now: the pole and each image an arrow drawn ends on.
  std::vector<kinematics::PolygonImage> drawnImages() const;

  /// Line widths and text sizes × `scale` (presentation mode: about 2).
  void setPresentationScale(double scale);

  QSize sizeHint() const override { return {460, 420}; }
  QSize minimumSizeHint() const override { return {240, 200}; }

signals:
  /// The widget was resized: the fitting scale may have changed.
  void resized();

protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  QFont scaledFont() const;
  QPointF toPixels(const Eigen::Vector2d& p) const;
  void drawArrow(QPainter& painter, const kinematics::PolygonVector& v) const;
  void drawImages(QPainter& painter, LabelLayout& layout) const;
  void drawVectorLabels(QPainter& painter, LabelLayout& layout) const;
  void drawScaleBar(QPainter& painter) const;
  void drawLegend(QPainter& painter) const;

  kinematics::VectorPolygon m_polygon;
  double m_chosenScale = 0.0;
  int m_revealed = kAllSteps;
  double m_presentationScale = 1.0;
};

}  // namespace linkwright::ui
