#include "ui/plots/plot_area_alignment.h"

#include "ui/plots/plot_axes.h"

#include <QChart>
#include <QGraphicsLayout>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

void alignPlotAreas(const QList<QChart*>& charts) { alignPlotAreas(charts, charts); }

void alignPlotAreas(const QList<QChart*>& charts, const QList<QChart*>& changed) {
  if (charts.isEmpty()) return;
  // The plot area's left edge is the left margin, which holds the base, the room of the y
  // axis' labels and title (plot_axes.h) and what alignment adds; its right edge the width
  // less the right margin and the legend. So each chart's natural insets (with the base
  // margins and its axes' room) follow from one layout pass at its current margins, which is
  // the pass the next paint needs anyway; activating it here just makes plotArea() current. Insets,
  // not edges, are matched: while a layout resizes the views one after another their widths
  // differ for a moment, and matching right edges then would pad the narrower ones hugely
  // (and QChartView never lowers a minimum size it once raised).
  struct Insets {
    qreal left = 0.0;
    qreal right = 0.0;
  };
  QList<Insets> natural;
  for (QChart* chart : charts) {
    // Afresh where something changed: Qt Charts does not invalidate its layout for every
    // change that moves the plot area (a legend marker shown). An unchanged chart's layout is
    // still valid (or pending after a resize), so activating it costs nothing or what the next
    // paint needs anyway.
    if (changed.contains(chart)) chart->layout()->invalidate();
    chart->layout()->activate();
    const QRectF area = chart->plotArea();
    const QMargins extra = chart->margins() - kBaseChartMargins - axesRoom(chart);
    natural.append({area.left() - extra.left(), chart->size().width() - area.right() - extra.right()});
  }
  Insets common = natural[0];
  for (const Insets& n : natural) {
    common.left = std::max(common.left, n.left);
    common.right = std::max(common.right, n.right);
  }
  for (qsizetype i = 0; i < charts.size(); ++i) {
    QMargins margins = kBaseChartMargins + axesRoom(charts[i]);
    margins.setLeft(margins.left() + static_cast<int>(std::lround(common.left - natural[i].left)));
    margins.setRight(margins.right() + static_cast<int>(std::lround(common.right - natural[i].right)));
    // Unchanged margins leave the layout valid: no second pass.
    if (margins != charts[i]->margins()) charts[i]->setMargins(margins);
  }
}

}  // namespace linkwright::ui
