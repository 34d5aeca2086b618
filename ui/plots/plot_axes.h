#pragma once
// The value axes of a chart (the labelled lines along the bottom and the left of its plot
// area), drawn by one item of ours in place of Qt Charts' own. Qt Charts lays an axis out
// afresh for every new range, each label a rich-text document shaped again (1–3 ms, a slow
// frame whenever a drag moves an axis), and repaints each label as a separate item. Its axes
// stay as the charts' scales, hidden; this item draws their lines, ticks, labels and titles
// in their pens, fonts and colours, and keeps the room they need as chart margins.

#include <QGraphicsObject>
#include <QMargins>
#include <QRectF>
#include <QStaticText>
#include <QStringList>

#include <vector>

class QChart;
class QFontMetricsF;
class QValueAxis;

namespace linkwright::ui {

class PlotAxesItem : public QGraphicsObject {
public:
  /// Hides Qt Charts' items of `xAxis` (bottom) and `yAxis` (left) of `chart` and draws the
  /// axes instead; adds the room they need to the chart's margins. The chart owns the item.
  PlotAxesItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis);

  /// What the labels and titles take around the plot area (part of the chart's margins).
  QMargins room() const { return m_room; }
  /// The tick labels as drawn, in tick order, of the horizontal (x) or vertical (y) axis.
  QStringList labels(Qt::Orientation orientation) const;
  /// The title as drawn (fittedTitle to its side of the plot area), empty while hidden.
  QString title(Qt::Orientation orientation) const;
  /// Shows or hides the title of the horizontal (x) or vertical (y) axis (shown at first); its
  /// text is the axis's titleText(). Qt Charts' own title stays hidden: shown again on a hidden
  /// axis, Qt drew it unplaced at the chart's top-left (after presentation mode on and off).
  void setTitleShown(Qt::Orientation orientation, bool shown);
  bool titleShown(Qt::Orientation orientation) const;

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  struct Axis {
    QValueAxis* axis;
    std::vector<QStaticText> labels;
    QStaticText title;    // elided to the plot area's side
    bool titled = true;   // the title is drawn
    double widest = 0.0;  // the widest label, px
    double depth = 0.0;   // how far the labels reach away from the plot area, px
  };
  // From the plot area's edge, where the title's text starts, and where the axis ends.
  static double titleOffset(const Axis& axis);
  static double reach(const Axis& axis);

  void follow(QValueAxis* axis);
  // New texts for new ranges, ticks, formats, fonts or titles, and the room they need.
  void relabel();
  void relabel(Axis& axis) const;
  void retitle(Axis& axis, double length) const;
  void setRoom(const QMargins& room);
  void paintX(QPainter* painter, const QRectF& exposed) const;
  void paintY(QPainter* painter, const QRectF& exposed) const;

  QChart* m_chart;
  Axis m_x;
  Axis m_y;
  QRectF m_area;  // the plot area, chart coordinates
  QMargins m_room;
};

/// `title` as drawn along a side `length` px long in `metrics`' font: whole when it fits, else
/// its name cut short ("angular acc… [deg/s²]") or left out, its unit ("[…]") always whole.
QString fittedTitle(const QString& title, const QFontMetricsF& metrics, double length);

/// The room `chart`'s PlotAxesItem keeps in its margins; none for a chart without one.
QMargins axesRoom(const QChart* chart);
/// `chart`'s PlotAxesItem, or nullptr.
PlotAxesItem* plotAxes(const QChart* chart);

}  // namespace linkwright::ui
