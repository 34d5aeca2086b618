#pragma once
// How every chart view of the plots draws: antialiased, its scene without an item index.

#include <QChartView>
#include <QGraphicsScene>

namespace linkwright::ui {

/// Sets up `view` (which holds its chart already) as the plots draw.
inline void setUpChartView(QChartView* view) {
  view->setRenderHint(QPainter::Antialiasing);
  // A chart's items move on every frame of a drag, and Qt's BSP index is rebuilt for each
  // move; a chart has a few dozen items, which a plain search finds as fast (Qt's advice for
  // scenes whose items move).
  view->scene()->setItemIndexMethod(QGraphicsScene::NoIndex);
}

}  // namespace linkwright::ui
