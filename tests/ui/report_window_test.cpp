// Report ▸ PDF: the designer writes the report `linkwright-cli report` writes (the same core
// calls), read back with pdftotext; a step the core refuses writes nothing and says why.

#include "ui/document/design_templates.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/report_options_dialog.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"

#include "app/cli/cli.h"
#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <sstream>
#include <string>
#include <vector>

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

// The designer's report of `example` drawn at `at` every `step` in `units`, and the CLI's with
// `options`, written into `dir` as gui.pdf and cli.pdf.
void writeBoth(ui::MainWindow& window, const QTemporaryDir& dir, const std::string& example, double at, double step,
               std::vector<std::string> options, const kinematics::report::ReportUnits& units = {}) {
  window.document()->reset(*kinematics::designForExample(example));
  REQUIRE(window.exportReport(dir.filePath("gui.pdf"), at, step, kinematics::report::Paper::A4, units));
  std::vector<std::string> args{"report", "--example", example, "-o", dir.filePath("cli.pdf").toStdString()};
  args.insert(args.end(), options.begin(), options.end());
  std::ostringstream out, err;
  REQUIRE(cli::runCli(args, out, err) == 0);
}

// Page 1's heading: the title line and the lines under it before "Lab report by Linkwright".
QStringList headingOf(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral(LINKWRIGHT_PDFTOTEXT), {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"),
                                                 QStringLiteral("1"), pdf, QStringLiteral("-")});
  REQUIRE(p.waitForFinished());
  QStringList heading;
  for (const QString& line : QString::fromUtf8(p.readAllStandardOutput()).split(QLatin1Char('\n'))) {
    if (line.startsWith(QStringLiteral("Lab report by Linkwright"))) break;
    if (!line.isEmpty()) heading << line;
  }
  return heading;
}

}  // namespace

TEST_CASE("Report ▸ PDF is headed by the example's or the file's name, what it is under it", "[ui][window][report]") {
  ui::MainWindow window;  // on its default example
  QTemporaryDir dir;
  const kinematics::Example thesis = *kinematics::findExample("thesis-crank-rocker");
  REQUIRE(window.exportReport(dir.filePath("example.pdf"), 0.0, 30.0, kinematics::report::Paper::A4));
  // (The description is one paragraph, which may wrap.)
  const QStringList example = headingOf(dir.filePath("example.pdf"));
  REQUIRE_FALSE(example.isEmpty());
  CHECK(example.front() == QStringLiteral("thesis-crank-rocker"));
  CHECK(example.mid(1).join(QLatin1Char(' ')) == QString::fromStdString(thesis.description));
  // File ▸ New ▸ Four-bar: named after its kind, so no line under it repeats it (issue 57: the
  // report was headed "four-bar" over "four-bar" whatever the document).
  window.newDocument(ui::templateDesign(ui::designTemplates().front()));
  REQUIRE(window.exportReport(dir.filePath("new.pdf"), 0.0, 30.0, kinematics::report::Paper::A4));
  CHECK(headingOf(dir.filePath("new.pdf")) == QStringList{QString::fromStdString(window.document()->design().kind)});
  REQUIRE(window.saveTo(dir.filePath("lecture.linkwright")));
  REQUIRE(window.exportReport(dir.filePath("saved.pdf"), 0.0, 30.0, kinematics::report::Paper::A4));
  CHECK(headingOf(dir.filePath("saved.pdf")) ==
        QStringList{QStringLiteral("lecture.linkwright"), QString::fromStdString(window.document()->design().kind)});
}

TEST_CASE("Report ▸ PDF writes the table linkwright-cli report writes", "[ui][window][report]") {
  ui::MainWindow window;
  QTemporaryDir dir;
  writeBoth(window, dir, "thesis-crank-rocker", 0.0, 30.0, {});
  const QString table = pageText(dir.filePath("gui.pdf"), 2);
  CHECK(table.contains(QStringLiteral("rocker ω")));
  CHECK(table == pageText(dir.filePath("cli.pdf"), 2));

  const QString refused = dir.filePath("refused.pdf");
  CHECK_FALSE(window.exportReport(refused, 0.0, 0.0, kinematics::report::Paper::A4));
  CHECK_FALSE(QFile::exists(refused));
  CHECK(window.banner()->text().contains(QStringLiteral("step")));
}

TEST_CASE("Report ▸ PDF of a document on a time base tabulates in seconds, as the CLI", "[ui][window][report]") {
  ui::MainWindow window;
  QTemporaryDir dir;
  // Drawn at 2 s, a row every 0.5 s: the times the CLI's --at and --step take on a time base.
  writeBoth(window, dir, "excavator-boom", 2.0, 0.5, {"--at", "2", "--step", "0.5"});
  // The table; not the extremes: the boom's smallest angle is at the law's flat start, where
  // the refined time (about 1e-5 s) depends on the samples it is refined between.
  const auto tableOf = [](const QString& page) { return page.left(page.indexOf(QStringLiteral("Extremes"))); };
  const QString table = tableOf(pageText(dir.filePath("gui.pdf"), 2));
  CHECK(table.contains(QStringLiteral("every 0.5 s")));
  CHECK(table.contains(QStringLiteral("2.0000")));
  CHECK(table == tableOf(pageText(dir.filePath("cli.pdf"), 2)));
}

TEST_CASE("Report ▸ PDF offers the three unit conventions, and radians reach the table", "[ui][window][report]") {
  namespace kr = kinematics::report;
  ui::ReportOptionsDialog dialog(0.0, 360.0, QStringLiteral("°"));
  REQUIRE(dialog.unitsBox()->count() == 3);
  for (const kr::ReportUnits units : {kr::ReportUnits{kr::AngleUnit::Degrees, kr::RateUnit::Radians},
                                      kr::ReportUnits{kr::AngleUnit::Degrees, kr::RateUnit::Degrees},
                                      kr::ReportUnits{kr::AngleUnit::Radians, kr::RateUnit::Radians}}) {
    dialog.setUnits(units);
    CHECK(dialog.units() == units);
  }
  ui::MainWindow window;
  QTemporaryDir dir;
  writeBoth(window, dir, "thesis-crank-rocker", 0.0, 30.0, {"--angles", "rad"},
            {kr::AngleUnit::Radians, kr::RateUnit::Radians});
  const QString table = pageText(dir.filePath("gui.pdf"), 2);
  CHECK(table.contains(QStringLiteral("(rad)")));
  CHECK(table == pageText(dir.filePath("cli.pdf"), 2));
}
