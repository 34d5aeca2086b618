// Report ▸ PDF: the designer writes the report `linkwright-cli report` writes (the same core
// calls), read back with pdftotext; a step the core refuses writes nothing and says why.

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"

#include "app/cli/cli.h"
#include "kinematics/design/design.h"

#include <catch2/catch.hpp>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <sstream>

using namespace linkwright;

namespace {

// Page `page` of a PDF as text, without its footer (the title and date differ: a document
// has no example name) and without the extremes' caption: the designer refines them from its
// document's grid (721 samples for the thesis example), the CLI from the example's table grid
// (every 30°), and both land on the same extremes.
QString pageText(const QString& pdf, int page) {
  QProcess p;
  p.start(QStringLiteral(LINKWRIGHT_PDFTOTEXT),
          {QStringLiteral("-layout"), QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"),
           QString::number(page), pdf, QStringLiteral("-")});
  REQUIRE(p.waitForFinished());
  QStringList lines = QString::fromUtf8(p.readAllStandardOutput()).split(QLatin1Char('\n'));
  lines.removeIf([](const QString& line) {
    return line.contains(QStringLiteral(" of ")) || line.contains(QStringLiteral("refined between"));
  });
  return lines.join(QLatin1Char('\n'));
}

}  // namespace

TEST_CASE("Report ▸ PDF writes the table linkwright-cli report writes", "[ui][window][report]") {
  ui::MainWindow window;
  window.document()->reset(*kinematics::designForExample("thesis-crank-rocker"));
  QTemporaryDir dir;
  const QString gui = dir.filePath("gui.pdf"), cli = dir.filePath("cli.pdf");
  REQUIRE(window.exportReport(gui, 0.0, 30.0, kinematics::report::Paper::A4));
  std::ostringstream out, err;
  REQUIRE(cli::runCli({"report", "--example", "thesis-crank-rocker", "-o", cli.toStdString()}, out, err) == 0);
  const QString table = pageText(gui, 2);
  CHECK(table.contains(QStringLiteral("rocker ω")));
  CHECK(table == pageText(cli, 2));

  const QString refused = dir.filePath("refused.pdf");
  CHECK_FALSE(window.exportReport(refused, 0.0, 0.0, kinematics::report::Paper::A4));
  CHECK_FALSE(QFile::exists(refused));
  CHECK(window.banner()->text().contains(QStringLiteral("step")));
}
