// Tests ui/plots/plot_grid.h: the grid lines drawn where Qt Charts draws its own, in one item.
#include "ui/plots/plot_grid.h"

#include "ui/plots/crank_angle_chart.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QGraphicsLayout>
#include <QGraphicsLineItem>
#include <QImage>
#include <QValueAxis>

#include "tests/support/catch.h"

#include <algorithm>
#include <vector>

using namespace linkwright::ui;

namespace {

const QColor kGridColour(200, 0, 0);

// The chart's axes as the plots set them: crank angle with ticks every 45° from 0, a value
// axis with six fixed ticks; grid lines in an unmistakable colour.
void setAxes(QValueAxis* x, QValueAxis* y) {
  x->setTickType(QValueAxis::TicksDynamic);
  x->setTickAnchor(0.0);
  x->setTickInterval(45.0);
  x->setRange(-10.0, 370.0);
  y->setRange(-3.0, 7.0);
  y->setTickCount(6);
  for (QValueAxis* axis : {x, y}) axis->setGridLinePen(QPen(kGridColour, 1.0));
}

void settle(QChartView& view) {
  view.resize(520, 320);
  view.show();
  QApplication::processEvents();
  view.chart()->layout()->activate();
  QApplication::processEvents();
}

// Where Qt Charts drew its own grid lines: the visible line items in the grid colour, as x of
// the vertical ones or y of the horizontal ones.
std::vector<double> qtGridLines(const QChart& chart, Qt::Orientation orientation) {
  std::vector<double> at;
  for (QGraphicsItem* item : chart.scene()->items()) {
    const auto* line = dynamic_cast<QGraphicsLineItem*>(item);
    if (line == nullptr || !line->isVisible() || line->pen().color() != kGridColour) continue;
    const QLineF l = line->line();
    if (orientation == Qt::Vertical && l.x1() == l.x2()) at.push_back(l.x1());
    if (orientation == Qt::Horizontal && l.y1() == l.y2()) at.push_back(l.y1());
  }
  std::sort(at.begin(), at.end());
  return at;
}

std::vector<double> inside(std::vector<double> pixels, double a, double b) {
  std::erase_if(pixels, [&](double p) { return p < std::min(a, b) || p > std::max(a, b); });
  std::sort(pixels.begin(), pixels.end());
  return pixels;
}

}  // namespace

TEST_CASE("majorTickPixels puts the grid lines where Qt Charts puts its own", "[plots][grid]") {
  QChartView view;
  auto* chart = new QChart;
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  view.setChart(chart);
  setAxes(x, y);
  settle(view);
  const QRectF area = chart->plotArea();
  REQUIRE(area.width() > 100.0);

  // 0, 45, …, 360 within -10…370: nine vertical lines; six horizontal ones.
  const std::vector<double> columns = inside(majorTickPixels(*x, area.left(), area.right()), area.left(), area.right());
  const std::vector<double> qtColumns = qtGridLines(*chart, Qt::Vertical);
  REQUIRE(columns.size() == 9);
  REQUIRE(qtColumns.size() == columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) CHECK(columns[i] == Approx(qtColumns[i]).margin(1e-9));
  CHECK(columns.front() == Approx(area.left() + 10.0 / 380.0 * area.width()));

  const std::vector<double> rows = inside(majorTickPixels(*y, area.bottom(), area.top()), area.top(), area.bottom());
  const std::vector<double> qtRows = qtGridLines(*chart, Qt::Horizontal);
  REQUIRE(rows.size() == 6);
  REQUIRE(qtRows.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(rows[i] == Approx(qtRows[i]).margin(1e-9));
}

TEST_CASE("majorTickPixels of an empty range or a degenerate tick setting is empty", "[plots][grid]") {
  QValueAxis axis;
  axis.setRange(2.0, 2.0);
  CHECK(majorTickPixels(axis, 0.0, 100.0).empty());
  axis.setRange(0.0, 10.0);
  axis.setTickType(QValueAxis::TicksDynamic);
  axis.setTickInterval(0.0);
  CHECK(majorTickPixels(axis, 0.0, 100.0).empty());
  axis.setTickInterval(1e-9);  // would be ten billion lines: bounded
  CHECK(majorTickPixels(axis, 0.0, 100.0).size() <= 1000);
  axis.setTickType(QValueAxis::TicksFixed);
  axis.setTickCount(3);
  axis.setReverse(true);  // the maximum drawn at `from`
  CHECK(majorTickPixels(axis, 0.0, 100.0) == std::vector<double>{100.0, 50.0, 0.0});
}

TEST_CASE("A crank-angle chart draws its grid as one-pixel lines at Qt's ticks, and follows the axes",
          "[plots][grid]") {
  QChartView view;
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  view.setChart(makeCrankAngleChart(QStringLiteral("angles"), x, y));
  setAxes(x, y);
  settle(view);
  QChart* chart = view.chart();
  // Qt Charts' own lines are hidden: the item draws them.
  CHECK_FALSE(x->isGridLineVisible());
  CHECK_FALSE(y->isGridLineVisible());
  CHECK(qtGridLines(*chart, Qt::Vertical).empty());
  const auto* grid = [&]() -> const PlotGridItem* {
    for (QGraphicsItem* item : chart->scene()->items())
      if (const auto* g = dynamic_cast<const PlotGridItem*>(item)) return g;
    return nullptr;
  }();
  REQUIRE(grid != nullptr);

  const QRectF area = chart->plotArea();
  const std::vector<int> columns = grid->columns();
  REQUIRE(columns.size() == 9);
  const std::vector<double> ticks = inside(majorTickPixels(*x, area.left(), area.right()), area.left(), area.right());
  for (std::size_t i = 0; i < columns.size(); ++i) CHECK(columns[i] == gridPixel(ticks[i]));
  REQUIRE(grid->rows().size() == 6);

  // Painted: each column in the grid's colour down the plot area, the columns between not.
  const int midRow = (grid->rows()[2] + grid->rows()[3]) / 2;
  QImage image = view.grab().toImage();
  for (const int column : columns) CHECK(image.pixelColor(column, midRow) == kGridColour);
  const int between = (columns[3] + columns[4]) / 2;
  CHECK(image.pixelColor(between, midRow) != kGridColour);
  // The first row is under the crank-angle axis's own line.
  for (std::size_t i = 1; i < grid->rows().size(); ++i)
    CHECK(image.pixelColor(between, grid->rows()[i]) == kGridColour);

  // A new range moves the lines; a new pen recolours them.
  x->setRange(0.0, 180.0);
  const QColor blue(0, 0, 200);
  y->setGridLinePen(QPen(blue, 1.0));
  QApplication::processEvents();
  const std::vector<int> moved = grid->columns();
  REQUIRE(moved.size() == 5);  // 0, 45, …, 180: both ends on the plot area's edges
  CHECK(moved.front() == gridPixel(area.left()));
  CHECK(moved.back() == gridPixel(area.right()));
  image = view.grab().toImage();
  CHECK(image.pixelColor(moved[1], midRow) == kGridColour);
  CHECK(image.pixelColor(between, grid->rows()[1]) == blue);
}
