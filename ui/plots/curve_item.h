#pragma once
// A curve's line on a chart, drawn by one item of ours in place of Qt Charts' line series.
// A QLineSeries strokes an outline of its whole line (its hover shape) every time its points
// are replaced, and paints the line one antialiased segment at a time: on a drag that was a
// third of the plots' cost (docs/benchmarks.md). This item keeps its vertices in plot units,
// maps them through the chart's axes when it paints, draws every segment in one call, and
// outlines the runs for hovering only when the mouse asks (shape()).
//
// The curve's name in the legend stays a Qt Charts series (empty, never drawn): the item
// takes its pen from that series, so a theme or presentation scale that sets the series' pen
// sets the line's.

#include <QGraphicsObject>
#include <QLineF>
#include <QList>
#include <QPainterPath>
#include <QPointF>

#include <optional>

class QChart;
class QValueAxis;
class QXYSeries;

namespace linkwright::ui {

class CurveItem : public QGraphicsObject {
  Q_OBJECT
public:
  /// A line over `chart`'s plot area, on `xAxis` and `yAxis`, in the pen of `legendEntry`
  /// (a series of the chart, which names the curve in the legend). The chart owns the item.
  CurveItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, const QXYSeries* legendEntry);

  /// Draws `runs` (plot units), each as one line; no line joins one run to the next.
  void setRuns(QList<QList<QPointF>> runs);
  /// The vertices drawn, run after run, in plot units.
  const QList<QList<QPointF>>& runs() const { return m_runs; }
  QPen pen() const;

  /// Where `value` (plot units) is drawn, in chart coordinates.
  QPointF toChart(QPointF value) const;
  /// The plot units drawn at `point` (chart coordinates).
  QPointF toValue(QPointF point) const;

  QRectF boundingRect() const override;
  /// The runs stroked wide enough to point at; made when first asked after a change.
  QPainterPath shape() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

signals:
  /// The mouse entered or moved along (`inside`) or left run `run`; `value` is where it
  /// points, in plot units.
  void hovered(qsizetype run, QPointF value, bool inside);
  /// setRuns gave the line new vertices.
  void runsReplaced();

protected:
  void hoverMoveEvent(QGraphicsSceneHoverEvent* event) override;
  void hoverLeaveEvent(QGraphicsSceneHoverEvent* event) override;

private:
  // Plot units to chart coordinates: chart = offset + value × scale, per axis.
  struct Mapping {
    QPointF offset;
    QPointF scale;
    qreal penWidth = 0.0;
    bool operator==(const Mapping&) const = default;
    QPointF operator()(QPointF value) const {
      return {offset.x() + value.x() * scale.x(), offset.y() + value.y() * scale.y()};
    }
  };
  Mapping mapping() const;
  qsizetype nearestRun(QPointF point) const;  // chart coordinates
  void placeBounds();                         // boundingRect() for the runs, axes and plot area now
  QRectF clipRect() const;                    // where the line may paint, chart coordinates

  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  const QXYSeries* m_legendEntry;
  QRectF m_area;  // the plot area, chart coordinates
  QList<QList<QPointF>> m_runs;
  bool m_hasVertices = false;
  QRectF m_valueBounds;          // of the vertices, plot units
  QRectF m_bounds;               // boundingRect(), chart coordinates
  qsizetype m_hoveredRun = -1;   // the run the mouse is on, or -1
  QList<QLineF> m_segments;      // the runs' segments in chart coordinates, reused by paint
  mutable QPainterPath m_shape;  // shape() as of m_shapeMapping
  mutable std::optional<Mapping> m_shapeMapping;
};

}  // namespace linkwright::ui
