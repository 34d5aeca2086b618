// File ▸ Export ▸ Image as PDF: one page the view's size (1 px = 0.75 pt, rounded to the whole
// points Qt's PDF pages have), vector (no picture
// inside, as poppler's pdfimages lists; the labels are text pdftotext reads), for the canvas and
// for one plot, through the one writer (an old file is kept when the write fails).

#include "ui/export/view_image.h"
#include "ui/canvas/linkage_view.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"
#include "ui/plots/plot_panel.h"

#include "tests/support/file_size_limit.h"
#include "tests/ui/support/read_file.h"

#include "tests/support/catch.h"
#include "tests/ui/support/settled_window.h"

#include <QApplication>
#include <QDir>
#include <QGraphicsView>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace linkwright;

using linkwright::test::showSettled;

namespace {

QString run(const char* program, const QStringList& arguments) {
  QProcess p;
  p.start(QString::fromUtf8(program), arguments);
  REQUIRE(p.waitForFinished());
  REQUIRE(p.exitCode() == 0);
  return QString::fromUtf8(p.readAllStandardOutput());
}

// pdfinfo's "Page size:      600 x 450 pts".
QSizeF pageSize(const QString& pdf) {
  const auto match = QRegularExpression(QStringLiteral("Page size:\\s+([0-9.]+) x ([0-9.]+) pts"))
                         .match(run(LINKWRIGHT_PDFINFO, {pdf}));
  REQUIRE(match.hasMatch());
  return {match.captured(1).toDouble(), match.captured(2).toDouble()};
}

// pdfimages -list prints two header lines, then one line per image.
int imageCount(const QString& pdf) {
  return int(run(LINKWRIGHT_PDFIMAGES, {QStringLiteral("-list"), pdf}).trimmed().split(QLatin1Char('\n')).size()) - 2;
}

}  // namespace

TEST_CASE("the canvas and a plot export as one vector PDF page of their size", "[ui][export][pdf]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;

  const QString canvas = dir.filePath("canvas.pdf");
  REQUIRE(window.exportCanvasImage(canvas));
  const QSize shown = window.canvas()->viewport()->size();
  CHECK(run(LINKWRIGHT_PDFINFO, {canvas}).contains(QRegularExpression(QStringLiteral("Pages:\\s+1\n"))));
  CHECK(pageSize(canvas).width() == Approx(shown.width() * 0.75).margin(0.5));
  CHECK(pageSize(canvas).height() == Approx(shown.height() * 0.75).margin(0.5));
  CHECK(imageCount(canvas) == 0);
  // The thesis crank-rocker's point names and the grid's unit are text, not pixels.
  const QString canvasText = run(LINKWRIGHT_PDFTOTEXT, {canvas, QStringLiteral("-")});
  CAPTURE(canvasText.toStdString());
  CHECK(canvasText.contains(QRegularExpression(QStringLiteral("\\bB\\b"))));
  CHECK(canvasText.contains(QStringLiteral("mm")));

  const QString plot = dir.filePath("plot.pdf");
  REQUIRE(window.exportPlotImage(0, plot));
  const QSize chart = window.plots()->graphicsViews()[0]->viewport()->size();
  CHECK(pageSize(plot).width() == Approx(chart.width() * 0.75).margin(0.5));
  CHECK(imageCount(plot) == 0);
  const QString plotText = run(LINKWRIGHT_PDFTOTEXT, {plot, QStringLiteral("-")});
  CAPTURE(plotText.toStdString());
  CHECK(plotText.contains(window.plots()->chartTitle(0).left(12)));
}

TEST_CASE("a PDF that cannot be written keeps the file that was there", "[ui][export][pdf][errors]") {
  ui::MainWindow window;
  showSettled(window);
  QTemporaryDir dir;
  const QString path = dir.filePath("figure.pdf");
  {
    QFile old(path);
    REQUIRE(old.open(QIODevice::WriteOnly));
    old.write("old contents");
  }
  {
    test::FileSizeLimit full(100);
    CHECK_FALSE(window.exportCanvasImage(path));
  }
  CHECK(window.banner()->text() == "Cannot write figure.pdf: File too large. The previous file, if any, is unchanged.");
  CHECK(test::readAll(path) == "old contents");
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"figure.pdf"});
  CHECK_FALSE(window.exportCanvasImage(dir.filePath("figure.jpg")));
  CHECK(window.banner()->text() == "Cannot export figure.jpg: use a .png, .svg or .pdf file name.");
}
