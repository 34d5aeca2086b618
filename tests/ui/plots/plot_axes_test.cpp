// Tests ui/plots/plot_axes.h: a chart's value axes drawn by one item of ours, Qt Charts' own
// hidden, with the room the labels and titles need kept in the chart's margins.
#include "ui/plots/plot_axes.h"

#include "ui/plots/chart_scale.h"
#include "ui/plots/crank_angle_chart.h"
#include "ui/plots/plot_area_alignment.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGraphicsTextItem>
#include <QImage>
#include <QPainter>
#include <QValueAxis>

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <utility>

using namespace linkwright::ui;

namespace {

const QColor kLabelColour(0, 0, 255);
const QColor kTitleColour(0, 160, 0);

// A crank-angle chart as the plots make it: 0–360° with a tick every 90°, a value axis of
// five fixed ticks, both titled.
struct Chart {
  QChartView view;
  QValueAxis* x = new QValueAxis;
  QValueAxis* y = new QValueAxis;
  QChart* chart = makeCrankAngleChart(QStringLiteral("Link angles"), x, y);
  PlotAxesItem* axes = nullptr;

  Chart() {
    view.setChart(chart);
    applyAxisRange(x, {0.0, 360.0, 90.0, 5, 0});
    x->setTickInterval(90.0);
    x->setTitleText(QStringLiteral("crank angle [deg]"));
    applyAxisRange(y, {-50.0, 150.0, 50.0, 5, 0});
    y->setTitleText(QStringLiteral("angle [deg]"));
    for (QGraphicsItem* item : chart->childItems())
      if (auto* a = dynamic_cast<PlotAxesItem*>(item)) axes = a;
    view.resize(520, 320);
    view.show();
    settle();
  }
  void settle() {
    QApplication::processEvents();
    chart->layout()->activate();
    QApplication::processEvents();
  }
  QImage render() {
    QImage image(view.viewport()->size(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    view.render(&painter, QRectF(), view.viewport()->rect());
    return image;
  }
};

// Pixels of `colour` in `rect` of `image`. Antialiased glyph edges blend towards the white
// background; a summed channel difference under 60 (of 765) keeps only their solid cores.
int countNear(const QImage& image, const QRect& rect, const QColor& colour) {
  int n = 0;
  for (int y = std::max(0, rect.top()); y <= std::min(image.height() - 1, rect.bottom()); ++y)
    for (int x = std::max(0, rect.left()); x <= std::min(image.width() - 1, rect.right()); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) + std::abs(c.blue() - colour.blue()) <
          60)
        ++n;
    }
  return n;
}

double widest(const QFontMetricsF& metrics, const QStringList& texts) {
  double w = 0.0;
  for (const QString& t : texts) w = std::max(w, metrics.horizontalAdvance(t));
  return w;
}

}  // namespace

TEST_CASE("the axes label the ticks in the axis's format, and Qt Charts' own axes are hidden", "[plots][axes]") {
  Chart c;
  REQUIRE(c.axes != nullptr);
  CHECK(c.axes->labels(Qt::Horizontal) == QStringList{"0", "90", "180", "270", "360"});
  CHECK(c.axes->labels(Qt::Vertical) == QStringList{"-50", "0", "50", "100", "150"});
  CHECK(c.axes->title(Qt::Horizontal) == QStringLiteral("crank angle [deg]"));
  CHECK(c.axes->title(Qt::Vertical) == QStringLiteral("angle [deg]"));
  CHECK_FALSE(c.x->isVisible());
  CHECK_FALSE(c.y->isVisible());
  // Qt Charts shows none of its label or title items (the chart's own title stays).
  for (QGraphicsItem* item : c.chart->scene()->items())
    if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text != nullptr && text->isVisible())
      CHECK(text->toPlainText() == QStringLiteral("Link angles"));

  // A new range, ticks and format are followed at once.
  applyAxisRange(c.y, {0.0, 2.5, 0.5, 6, 1});
  CHECK(c.axes->labels(Qt::Vertical) == QStringList{"0.0", "0.5", "1.0", "1.5", "2.0", "2.5"});
}

TEST_CASE("a rounding error about zero is labelled 0, not -0", "[plots][axes]") {
  Chart c;
  c.y->setTickType(QValueAxis::TicksDynamic);
  c.y->setTickAnchor(0.3);  // the ticks reach 0 by adding 0.1 to -0.7: a few 1e-16 off
  c.y->setTickInterval(0.1);
  applyAxisRange(c.y, {-0.7, 0.7, 0.1, 15, 1});
  const QStringList labels = c.axes->labels(Qt::Vertical);
  REQUIRE(labels.size() == 15);
  CHECK(labels.front() == QStringLiteral("-0.7"));
  CHECK(labels.contains(QStringLiteral("0.0")));
  CHECK_FALSE(labels.contains(QStringLiteral("-0.0")));
}

TEST_CASE("huge values are labelled in scientific notation, not hundreds of digits", "[plots][axes]") {
  Chart c;
  applyAxisRange(c.y, {-2e300, 6e300, 2e300, 5, 0});
  c.settle();
  CHECK(c.axes->labels(Qt::Vertical) == QStringList{"-2e+300", "0", "2e+300", "4e+300", "6e+300"});
  // The plot keeps most of the chart's width.
  CHECK(c.chart->plotArea().width() > 0.5 * c.chart->size().width());
}

TEST_CASE("the chart keeps room for the labels and titles beside its plot area", "[plots][axes]") {
  Chart c;
  const QRectF before = c.chart->plotArea();
  const QMargins room = c.axes->room();
  // The margins hold the room: the plot area starts where the labels and title end.
  CHECK(c.chart->margins() == kBaseChartMargins + room);
  const QFontMetricsF labels(c.y->labelsFont());
  CHECK(room.left() >= labels.horizontalAdvance(QStringLiteral("-50")) + QFontMetricsF(c.y->titleFont()).height());
  CHECK(room.bottom() >= labels.height() + QFontMetricsF(c.x->titleFont()).height());
  CHECK(axesRoom(c.chart) == room);

  // Wider labels push the plot area right by as much as they grew.
  applyAxisRange(c.y, {-50000.0, 150000.0, 50000.0, 5, 0});
  c.settle();
  const double grown = widest(labels, c.axes->labels(Qt::Vertical)) - widest(labels, {"-50", "0", "50", "100", "150"});
  CHECK(c.chart->plotArea().left() - before.left() == Approx(grown).margin(1.0));
  CHECK(c.chart->margins() == kBaseChartMargins + c.axes->room());

  // A hidden title gives its room back to the plot.
  c.axes->setTitleShown(Qt::Horizontal, false);
  c.settle();
  CHECK(c.axes->title(Qt::Horizontal).isEmpty());
  CHECK(c.chart->plotArea().height() > before.height() + 0.9 * QFontMetricsF(c.x->titleFont()).height());
}

TEST_CASE("the labels and titles are painted beside the plot area, in the axes' colours", "[plots][axes]") {
  Chart c;
  for (QValueAxis* axis : {c.x, c.y}) {
    axis->setLabelsBrush(kLabelColour);
    axis->setTitleBrush(kTitleColour);
  }
  const QImage image = c.render();
  const QRect area = c.chart->plotArea().toAlignedRect();
  const QMargins room = c.axes->room();
  const QRect left(area.left() - room.left(), area.top(), room.left(), area.height());
  const QRect below(area.left(), area.bottom() + 1, area.width(), room.bottom());
  CHECK(countNear(image, left, kLabelColour) > 20);
  CHECK(countNear(image, below, kLabelColour) > 20);
  CHECK(countNear(image, left, kTitleColour) > 20);
  CHECK(countNear(image, below, kTitleColour) > 20);
  // Nothing of them inside the plot area.
  CHECK(countNear(image, area.adjusted(2, 2, -2, -2), kLabelColour) == 0);
  CHECK(countNear(image, area.adjusted(2, 2, -2, -2), kTitleColour) == 0);
  // The vertical title reads upwards: it is taller than wide.
  int top = image.height(), bottom = -1, leftmost = image.width(), rightmost = -1;
  for (int y = left.top(); y <= left.bottom(); ++y)
    for (int x = left.left(); x <= left.right(); ++x)
      if (countNear(image, QRect(x, y, 1, 1), kTitleColour) == 1) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
        leftmost = std::min(leftmost, x);
        rightmost = std::max(rightmost, x);
      }
  CHECK(bottom - top > 3 * (rightmost - leftmost));
}

TEST_CASE("a title longer than its side of the plot is cut short", "[plots][axes]") {
  Chart c;
  c.y->setTitleText(QString(200, QLatin1Char('w')));
  c.settle();
  const QString shown = c.axes->title(Qt::Vertical);
  CHECK(shown.endsWith(QChar(0x2026)));
  CHECK(QFontMetricsF(c.y->titleFont()).horizontalAdvance(shown) <= c.chart->plotArea().height());
}

TEST_CASE("a title too long for its side keeps its unit whole: the name is cut short, or left out", "[plots][axes]") {
  const QFont font;
  const QFontMetricsF metrics(font);
  const QString title = QStringLiteral("angular acceleration α [deg/s²]");
  CHECK(fittedTitle(title, metrics, 1000.0) == title);
  // Room for the unit and part of the name: the name is cut, the unit whole ("angle [d…" lost it).
  const double unitAndSome = metrics.horizontalAdvance(QStringLiteral("angular … [deg/s²]"));
  const QString cut = fittedTitle(title, metrics, unitAndSome);
  CHECK(cut.endsWith(QStringLiteral("… [deg/s²]")));
  CHECK(metrics.horizontalAdvance(cut) <= unitAndSome);
  // Less room than the unit: the unit alone, whole.
  CHECK(fittedTitle(title, metrics, 10.0) == QStringLiteral("[deg/s²]"));
  // A title without a unit is cut short as before.
  CHECK(fittedTitle(QStringLiteral("Driving torque"), metrics, 30.0).endsWith(QChar(0x2026)));
}

TEST_CASE("aligned charts keep each one's room and line up their plot areas", "[plots][axes]") {
  Chart narrow, wide;
  applyAxisRange(wide.y, {-50000.0, 150000.0, 50000.0, 5, 0});
  wide.settle();
  alignPlotAreas({narrow.chart, wide.chart});
  narrow.settle();
  wide.settle();
  CHECK(narrow.chart->plotArea().left() == Approx(wide.chart->plotArea().left()).margin(0.5));
  CHECK(narrow.chart->plotArea().right() == Approx(wide.chart->plotArea().right()).margin(0.5));
  // The narrow chart's labels are padded out, not moved: its room is its own.
  CHECK(narrow.chart->margins().left() > kBaseChartMargins.left() + narrow.axes->room().left());
  CHECK(wide.chart->margins() == kBaseChartMargins + wide.axes->room());
}

TEST_CASE("the axes follow the chart's scale, their titles still centred (presentation mode)", "[plots][axes]") {
  Chart c;
  c.view.resize(900, 520);
  c.settle();
  for (QValueAxis* axis : {c.x, c.y}) axis->setTitleBrush(kTitleColour);
  // The columns the x title's pixels span, below the plot area.
  const auto xTitleSpan = [&c] {
    const QImage image = c.render();
    const int below = c.chart->plotArea().toAlignedRect().bottom() + 1;
    std::pair<int, int> span{image.width(), -1};
    for (int y = below; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x)
        if (countNear(image, QRect(x, y, 1, 1), kTitleColour) == 1) {
          span.first = std::min(span.first, x);
          span.second = std::max(span.second, x);
        }
    return span;
  };
  // The depth of the x axis' texts (a line of labels and the title) at the fonts of the time.
  const auto textDepth = [&c] {
    return QFontMetricsF(c.x->labelsFont()).height() + QFontMetricsF(c.x->titleFont()).height();
  };
  const QMargins before = c.axes->room();
  const double depth1 = textDepth();
  const auto [left1, right1] = xTitleSpan();
  setChartScale(c.chart, 2.0);
  c.settle();
  // The room grows by what the texts grew (the paddings stay).
  CHECK(c.axes->room().bottom() - before.bottom() == Approx(textDepth() - depth1).margin(1.0));
  CHECK(c.axes->room().left() > before.left() + 10);
  // The title is drawn in its new font, twice as wide, and still centred under the plot area.
  const auto [left2, right2] = xTitleSpan();
  REQUIRE(right1 > left1);
  CHECK(right2 - left2 > 1.7 * (right1 - left1));
  CHECK(0.5 * (left2 + right2) == Approx(c.chart->plotArea().center().x()).margin(3.0));
}

// Presentation mode on a projector's 1024 px: the crank axis's five labels, 90° apart, ran
// together ("0 90 180270360"). The step is the least of 90, 180, 360 at which the labels keep a
// digit apart, whatever the font and the width.
TEST_CASE("the x axis labels a coarser step where its labels would run together", "[plots][axes]") {
  const linkwright::ui::AxisRange crank{0.0, 360.0, 90.0, 5, 0};
  for (const double points : {9.0, 16.0, 24.0}) {
    QFont font;
    font.setPointSizeF(points);
    const QFontMetricsF metrics(font);
    const double room =
        metrics.horizontalAdvance(QStringLiteral("360")) + metrics.horizontalAdvance(QStringLiteral("0"));
    for (const double width : {120.0, 200.0, 300.0, 600.0, 1200.0}) {
      CAPTURE(points, width);
      const double step = linkwright::ui::fittedTickStep(crank, width, font);
      CHECK((step == 90.0 || step == 180.0 || step == 360.0 || step > 360.0));
      if (step <= 360.0) CHECK(step * width / 360.0 >= room);     // apart
      if (step > 90.0) CHECK(step / 2.0 * width / 360.0 < room);  // the finer step would not be
    }
  }
  // Before the first layout, and for a range with no span, the range's own step.
  CHECK(linkwright::ui::fittedTickStep(crank, 0.0, QFont()) == 90.0);
}
