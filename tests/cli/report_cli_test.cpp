// Tests `linkwright-cli report`: the PDF it writes holds the solver's numbers (read back with
// poppler's pdftotext, a reader independent of the cairo that writes it), the page numbers and
// the Grashof class; the forces section appears with masses and the slider columns for a
// slider-crank; bad options are refused, naming the option, and nothing is written. The
// content model (kinematics/report/report_content.h) is checked against the sweep directly.

#include "tests/cli/run_cli.h"

#include "kinematics/design/examples.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/report/report_content.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace k = linkwright::kinematics;
namespace fs = std::filesystem;

namespace {

// The standard output of a shell command (pdftotext, pdfinfo).
std::string capture(const std::string& command) {
  std::string text;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  REQUIRE(pipe);
  std::array<char, 4096> buffer{};
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) text.append(buffer.data(), n);
  return text;
}

std::string pdfText(const fs::path& pdf) {
  return capture(std::string(LINKWRIGHT_PDFTOTEXT) + " -layout '" + pdf.string() + "' -");
}

int pdfPages(const fs::path& pdf) {
  const std::string info = capture(std::string(LINKWRIGHT_PDFINFO) + " '" + pdf.string() + "'");
  const auto at = info.find("Pages:");
  REQUIRE(at != std::string::npos);
  return std::stoi(info.substr(at + 6));
}

// True if one line of `text` holds `cells` in this order, as separate words.
bool hasRow(const std::string& text, const std::vector<std::string>& cells) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string word;
    std::size_t next = 0;
    while (next < cells.size() && words >> word)
      if (word == cells[next]) ++next;
    if (next == cells.size()) return true;
  }
  return false;
}

// Page 1's heading as read back: the title line, and what stands under it before the "Lab
// report by Linkwright" line (a paragraph, so joined into one line).
std::pair<std::string, std::string> pdfHeading(const fs::path& pdf) {
  std::istringstream lines(capture(std::string(LINKWRIGHT_PDFTOTEXT) + " -f 1 -l 1 '" + pdf.string() + "' -"));
  std::string line, title, subtitle;
  while (std::getline(lines, line) && line.rfind("Lab report by Linkwright", 0) != 0) {
    if (line.empty()) continue;
    if (title.empty()) title = line;
    else subtitle += (subtitle.empty() ? "" : " ") + line;
  }
  return {title, subtitle};
}

std::string fixed(double v) { return k::formatFixed(v, k::report::kTableDecimals); }

// The thesis crank-rocker's sweep every 30° from the example's own speed: what the table shows.
k::SweepResult thesisEvery30(const k::Example& e) {
  const k::SweepSpec spec{0.0, 2.0 * k::kPi, 13, e.omega, e.alpha};
  auto r = k::sweep(e.mechanism, spec);
  REQUIRE(r.ok());
  return std::move(r).value();
}

std::size_t linkIndex(const k::Mechanism& m, const std::string& name) {
  for (std::size_t i = 0; i < m.links.size(); ++i)
    if (m.links[i].name == name) return i;
  FAIL("no link " << name);
  return 0;
}

}  // namespace

TEST_CASE("report of the thesis crank-rocker holds the solver's table, pages and class", "[cli][report]") {
  const fs::path dir = scratchDir("report-cli");
  const fs::path file = dir / "thesis.pdf";
  const auto run = runCliCommand({"report", "--example", "thesis-crank-rocker", "-o", file.string()});
  REQUIRE(run.code == 0);
  CHECK_THAT(run.out, Catch::Contains("a table row every 30°"));
  // Title, drawing and analysis; the table and the extremes; the four plots of θ, ω, α and μ.
  const int pages = pdfPages(file);
  CHECK(pages == 3);
  const std::string text = pdfText(file);
  for (int p = 1; p <= pages; ++p)
    CHECK_THAT(text, Catch::Contains("page " + std::to_string(p) + " of " + std::to_string(pages)));
  CHECK_THAT(text, Catch::Contains("crank-rocker (shortest link: crank, longest: coupler)"));
  CHECK_THAT(text, Catch::Contains("M = 3(4 − 1) − 2·4 − 0 = 1"));
  CHECK_THAT(text, Catch::Contains("crank 25 mm"));

  const k::Example e = *k::findExample("thesis-crank-rocker");
  const k::SweepResult r = thesisEvery30(e);
  const std::size_t coupler = linkIndex(e.mechanism, "coupler"), rocker = linkIndex(e.mechanism, "rocker");
  for (std::size_t j = 0; j < r.size(); ++j) {
    INFO("crank angle " << 30 * j);
    // θ3, ω3, α3, θ4, ω4, α4 in the table's order and format (analyze's columns, 4 decimals).
    CHECK(hasRow(text, {fixed(30.0 * static_cast<double>(j)), fixed(k::radToDeg(r.linkAngle[coupler][j])),
                        fixed(r.linkOmega[coupler][j]), fixed(r.linkAlpha[coupler][j]),
                        fixed(k::radToDeg(r.linkAngle[rocker][j])), fixed(r.linkOmega[rocker][j]),
                        fixed(r.linkAlpha[rocker][j])}));
  }
  fs::remove_all(dir);
}

TEST_CASE("report is headed by the example's or the document's name, what it is under it", "[cli][report]") {
  const fs::path dir = scratchDir("report-heading");
  const k::Example e = *k::findExample("thesis-crank-rocker");
  REQUIRE(runCliCommand({"report", "--example", e.name, "-o", (dir / "example.pdf").string()}).code == 0);
  CHECK(pdfHeading(dir / "example.pdf") == std::pair<std::string, std::string>{e.name, e.description});
  CHECK_THAT(capture(std::string(LINKWRIGHT_PDFINFO) + " '" + (dir / "example.pdf").string() + "'"),
             Catch::Contains("Title:") && Catch::Contains(e.name));
  const std::string document = LINKWRIGHT_TEST_DOCUMENTS "/fourbar_v1.json";
  REQUIRE(runCliCommand({"report", document, "-o", (dir / "document.pdf").string()}).code == 0);
  CHECK(pdfHeading(dir / "document.pdf") == std::pair<std::string, std::string>{"fourbar_v1.json", "four-bar"});
  REQUIRE(runCliCommand({"report", "--fourbar", "60,25,70,45", "-o", (dir / "lengths.pdf").string()}).code == 0);
  // Lengths typed on the command line: the title says what it is, and nothing stands under it.
  CHECK(pdfHeading(dir / "lengths.pdf") == std::pair<std::string, std::string>{"Four-bar 60, 25, 70, 45 mm", ""});
  fs::remove_all(dir);
}

TEST_CASE("a report's heading says what the linkage is under its name, never its name twice", "[cli][report]") {
  k::report::ReportRequest request;
  k::report::setReportHeading(request, "thesis-crank-rocker", "Crank-rocker, 60/25/70/45 mm", "four-bar");
  CHECK((request.title == "thesis-crank-rocker" && request.subtitle == "Crank-rocker, 60/25/70/45 mm"));
  k::report::setReportHeading(request, "lecture.linkwright", "", "four-bar");
  CHECK((request.title == "lecture.linkwright" && request.subtitle == "four-bar"));
  // A new four-bar is named after its kind: the heading is not "four-bar" over "four-bar".
  k::report::setReportHeading(request, "four-bar", "", "four-bar");
  CHECK((request.title == "four-bar" && request.subtitle.empty()));
}

TEST_CASE("report's content model holds the sweep's numbers and extremes' refined values", "[cli][report]") {
  const k::Example e = *k::findExample("thesis-crank-rocker");
  k::report::ReportRequest request;
  request.title = "thesis";
  request.grid = {0.0, 2.0 * k::kPi, 13, e.omega, e.alpha};  // the example's grid, every 30°
  request.tableStep = k::degToRad(30.0);
  const auto report = k::report::buildReport(e.mechanism, {}, request);
  REQUIRE(report.ok());
  const k::SweepResult r = thesisEvery30(e);
  REQUIRE(report->table.values.size() == r.size());
  const std::size_t rocker = linkIndex(e.mechanism, "rocker");
  REQUIRE(report->table.columns[5].heading == "rocker ω");
  for (std::size_t j = 0; j < r.size(); ++j) CHECK(*report->table.values[j][5] == r.linkOmega[rocker][j]);
  // The extremes table prints what `extremes` prints for the same grid.
  const auto extremes = runCliCommand({"extremes", "--example", "thesis-crank-rocker"});
  REQUIRE(extremes.code == 0);
  REQUIRE(report->extremes.cells.size() >= 6);
  for (const auto& row : report->extremes.cells) CHECK(hasRow(extremes.out, row));
}

TEST_CASE("report --rates deg gives ω and α in deg/s and deg/s², the table, extremes and plots alike",
          "[cli][report]") {
  const fs::path dir = scratchDir("report-cli");
  const fs::path file = dir / "thesis-deg.pdf";
  REQUIRE(runCliCommand({"report", "--example", "thesis-crank-rocker", "--rates", "deg", "-o", file.string()}).code ==
          0);
  const std::string text = pdfText(file);
  CHECK_THAT(text, Catch::Contains("deg/s²"));
  CHECK_THAT(text, !Catch::Contains("rad/s²"));
  const k::Example e = *k::findExample("thesis-crank-rocker");
  const k::SweepResult r = thesisEvery30(e);
  const std::size_t coupler = linkIndex(e.mechanism, "coupler"), rocker = linkIndex(e.mechanism, "rocker");
  for (std::size_t j = 0; j < r.size(); ++j) {
    INFO("crank angle " << 30 * j);
    const auto deg = [](double v) { return fixed(k::radToDeg(v)); };
    CHECK(hasRow(text, {fixed(30.0 * static_cast<double>(j)), deg(r.linkAngle[coupler][j]),
                        deg(r.linkOmega[coupler][j]), deg(r.linkAlpha[coupler][j]), deg(r.linkAngle[rocker][j]),
                        deg(r.linkOmega[rocker][j]), deg(r.linkAlpha[rocker][j])}));
  }
  // The content model: the rates' extremes and curves are the radians' times 180/π, renamed.
  k::report::ReportRequest request;
  request.grid = {0.0, 2.0 * k::kPi, 13, e.omega, e.alpha};
  request.tableStep = k::degToRad(30.0);
  const auto radians = k::report::buildReport(e.mechanism, {}, request);
  request.units.rates = k::report::RateUnit::Degrees;
  const auto degrees = k::report::buildReport(e.mechanism, {}, request);
  REQUIRE(radians.ok());
  REQUIRE(degrees.ok());
  CHECK(degrees->table.columns[5].unit == "deg/s");
  CHECK(degrees->table.columns[4].unit == "deg");  // angles stay in degrees
  REQUIRE(degrees->extremes.cells.size() == radians->extremes.cells.size());
  int rates = 0;
  for (std::size_t i = 0; i < degrees->extremes.cells.size(); ++i) {
    const std::string& name = radians->extremes.cells[i][0];
    const bool rate = name.find("_rad_s") != std::string::npos;
    const double scale = rate ? k::radToDeg(1.0) : 1.0;
    CHECK(*degrees->extremes.values[i][1] == Approx(*radians->extremes.values[i][1] * scale).epsilon(1e-15));
    CHECK(*degrees->extremes.values[i][3] == Approx(*radians->extremes.values[i][3] * scale).epsilon(1e-15));
    if (rate) CHECK(degrees->extremes.cells[i][0].find("_deg_s") != std::string::npos);
    rates += rate;
  }
  CHECK(rates == 4);  // ω3, α3, ω4, α4
  // --angles rad: the link and transmission angles in radians, the input still in degrees.
  request.units = {k::report::AngleUnit::Radians, k::report::RateUnit::Radians};
  const auto inRadians = k::report::buildReport(e.mechanism, {}, request);
  REQUIRE(inRadians.ok());
  CHECK(inRadians->table.columns[0].unit == "deg");
  CHECK(inRadians->table.columns[4].unit == "rad");
  CHECK(inRadians->table.columns[5].unit == "rad/s");
  for (std::size_t j = 0; j < radians->table.values.size(); ++j) {
    CHECK(*inRadians->table.values[j][0] == *radians->table.values[j][0]);
    CHECK(*inRadians->table.values[j][4] == Approx(k::degToRad(*radians->table.values[j][4])).epsilon(1e-15));
    CHECK(*inRadians->table.values[j][5] == *radians->table.values[j][5]);
  }
  CHECK(inRadians->extremes.cells[0][0].ends_with("_angle_rad"));
  CHECK(inRadians->plots[0].yTitle == "rad");
  REQUIRE(degrees->plots.size() == radians->plots.size());
  CHECK(degrees->plots[1].yTitle == "deg/s");
  CHECK(degrees->plots[1].curves[0].segments[0][7].y() ==
        Approx(radians->plots[1].curves[0].segments[0][7].y() * k::radToDeg(1.0)).epsilon(1e-15));
  fs::remove_all(dir);
}

TEST_CASE("report of a linkage on a motion-law time base tabulates every --step seconds", "[cli][report]") {
  // The excavator boom: a cylinder extends from 1.2 to 1.9 m in 4 s on a cycloidal law.
  const fs::path dir = scratchDir("report-cli");
  const fs::path file = dir / "boom.pdf";
  const auto run =
      runCliCommand({"report", "--example", "excavator-boom", "--step", "0.5", "--at", "2", "-o", file.string()});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK_THAT(run.out, Catch::Contains("a table row every 0.5 s"));
  const std::string text = pdfText(file);
  CHECK_THAT(text, Catch::Contains("Time 0 s to 4 s, every 0.5 s; the driver follows its motion law"));
  CHECK_THAT(text, Catch::Contains("time (s)"));

  // The content model: a time column, one row every 0.5 s, each the sweep's at that instant.
  const k::Example e = *k::findExample("excavator-boom");
  REQUIRE(e.time);
  k::report::ReportRequest request;
  request.grid.samples = static_cast<std::size_t>(e.timeSamples);
  request.grid.time = e.time;
  request.tableStep = 0.5;
  request.drawAt = 2.0;
  const auto report = k::report::buildReport(e.mechanism, {}, request);
  REQUIRE(report.ok());
  REQUIRE(report->table.columns[0].heading == "time");
  REQUIRE(report->table.values.size() == 9);
  k::SweepSpec rows;
  rows.samples = 9;
  rows.time = e.time;
  const auto swept = k::sweep(e.mechanism, rows);
  REQUIRE(swept.ok());
  const auto columns = k::sweepColumns(e.mechanism, swept->request, true);
  for (std::size_t j = 0; j < 9; ++j) {
    CHECK(*report->table.values[j][0] == Approx(0.5 * static_cast<double>(j)).margin(1e-12));
    CHECK(hasRow(text, {fixed(0.5 * static_cast<double>(j))}));
    // Every tabulated column is analyze's column of the same name at that row.
    for (std::size_t c = 1; c < report->table.columns.size(); ++c) {
      if (!report->table.values[j][c]) continue;
      const std::string& heading = report->table.columns[c].heading;
      INFO(heading << " at " << 0.5 * static_cast<double>(j) << " s");
      bool found = false;
      for (const k::SweepColumn& column : columns)
        if (std::abs(column.value(*swept, j) - *report->table.values[j][c]) < 1e-9) found = true;
      CHECK(found);
    }
  }
  // The extremes are `extremes`' on the example's own time base, at their times.
  const auto extremes = runCliCommand({"extremes", "--example", "excavator-boom"});
  REQUIRE(extremes.code == 0);
  REQUIRE(report->extremes.columns[2].unit == "s");
  REQUIRE(report->extremes.cells.size() >= 4);
  for (const auto& row : report->extremes.cells) CHECK(hasRow(extremes.out, row));
  REQUIRE_FALSE(report->plots.empty());
  CHECK(report->plots.front().xTitle == "time (s)");

  // A step beyond the span, a time outside it: refused, naming them, nothing written.
  fs::remove(file);
  const auto longStep = runCliCommand({"report", "--example", "excavator-boom", "--step", "5", "-o", file.string()});
  CHECK(longStep.code == 2);
  CHECK_THAT(longStep.err, Catch::Contains("--step must be more than 0 and at most 4 s"));
  const auto late = runCliCommand({"report", "--example", "excavator-boom", "--at", "9", "-o", file.string()});
  CHECK(late.code == 2);
  CHECK_THAT(late.err, Catch::Contains("within the time span, 0 to 4 s (got 9 s)"));
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("report shows the forces of a linkage with masses", "[cli][report]") {
  const fs::path dir = scratchDir("report-cli");
  const fs::path file = dir / "funsho.pdf";
  const auto run = runCliCommand({"report", "--example", "funsho-fourbar", "--step", "45", "-o", file.string()});
  REQUIRE(run.code == 0);
  const std::string text = pdfText(file);
  CHECK_THAT(text, Catch::Contains("Forces"));
  CHECK_THAT(text, Catch::Contains("T_drive"));
  const k::Example e = *k::findExample("funsho-fourbar");
  const k::SweepSpec spec{0.0, 2.0 * k::kPi, 9, e.omega, e.alpha};
  const auto r = k::sweep(e.mechanism, spec);
  REQUIRE(r.ok());
  const auto forces = k::sweepForces(e.mechanism, e.dynamics, *r);
  REQUIRE(forces.ok());
  for (std::size_t j = 0; j < r->size(); ++j) {
    INFO("crank angle " << 45 * j);
    CHECK(hasRow(text, {fixed(45.0 * static_cast<double>(j)), fixed(forces->driveTorque[j])}));
  }
  // The peaks over the example's own grid, every 5°.
  const auto grid = k::sweep(e.mechanism, {0.0, 2.0 * k::kPi, 73, e.omega, e.alpha}).value();
  const auto all = k::sweepForces(e.mechanism, e.dynamics, grid).value();
  double peak = 0.0;
  for (std::size_t j = 0; j < all.size(); ++j) peak = std::max(peak, all.shakingForce[j].norm());
  std::string flat;  // the caption may wrap: words joined by single spaces
  for (const char c : text)
    if (!(std::isspace(static_cast<unsigned char>(c)) && (flat.empty() || flat.back() == ' ')))
      flat += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  // Refined between those samples on poses solved afresh, the peak is the one another method
  // finds: machine's, off the series of a whole turn. The best of the 73 samples is short of it.
  const auto machine = k::runMachine(e.mechanism, e.dynamics, k::machineDefaultsOf(k::sweepGridOf(e)),
                                     k::machineRequest({}, k::FrontEnd::Cli).value());
  REQUIRE(machine.ok());
  const double refined = machine->duty.shakingForcePeak;
  CHECK_THAT(flat, Catch::Contains("Refined between the cycle's 73 samples, the shaking force peaks at " +
                                   k::formatShort(refined, 4) + " N"));
  CHECK(refined >= peak);
  // The virtual-work check over the same grid, at round-off.
  const std::string check = "by virtual work differs from Newton–Euler's by at most ";
  const std::size_t at = flat.find(check);
  REQUIRE(at != std::string::npos);
  double torquePeak = 0.0;
  for (const double t : all.driveTorque) torquePeak = std::max(torquePeak, std::abs(t));
  CHECK(std::stod(flat.substr(at + check.size())) <= 1e-9 * torquePeak);
  fs::remove_all(dir);
}

TEST_CASE("report of a slider-crank tabulates the slider", "[cli][report]") {
  const fs::path dir = scratchDir("report-cli");
  const fs::path file = dir / "engine.pdf";
  const auto run = runCliCommand({"report", "--example", "ls3-engine", "--paper", "letter", "-o", file.string()});
  REQUIRE(run.code == 0);
  const std::string text = pdfText(file);
  const k::Example e = *k::findExample("ls3-engine");
  std::size_t slider = 0;
  for (std::size_t i = 0; i < e.mechanism.points.size(); ++i)
    if (std::holds_alternative<k::RrpPoint>(e.mechanism.points[i].definition)) slider = i;
  const std::string name = e.mechanism.points[slider].name;
  // (pdftotext joins "C x" into "Cx": the narrow space of a short heading.)
  CHECK_THAT(text, Catch::Contains(name + " vx") && Catch::Contains(name + " ax"));
  CHECK_THAT(text, Catch::Contains("Slider position"));
  const k::SweepSpec spec{0.0, 2.0 * k::kPi, 13, e.omega, e.alpha};
  const auto r = k::sweep(e.mechanism, spec);
  REQUIRE(r.ok());
  for (std::size_t j = 0; j < r->size(); ++j)
    CHECK(hasRow(text, {fixed(30.0 * static_cast<double>(j)), fixed(r->position[slider][j].x()),
                        fixed(r->velocity[slider][j].x()), fixed(r->acceleration[slider][j].x())}));
  CHECK_THAT(capture(std::string(LINKWRIGHT_PDFINFO) + " '" + file.string() + "'"), Catch::Contains("612 x 792 pts"));
  fs::remove_all(dir);
}

TEST_CASE("report refuses bad options, naming them, and writes nothing", "[cli][report][errors]") {
  const fs::path dir = scratchDir("report-cli");
  const std::string file = (dir / "r.pdf").string();
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string message;
  };
  const Case cases[] = {
      {{"--step", "0", "-o", file}, 2, "--step must be more than 0 and at most 360 degrees (got 0)"},
      {{"--step", "-30", "-o", file}, 2, "--step must be more than 0 and at most 360 degrees (got -30)"},
      {{"--step", "400", "-o", file}, 2, "--step must be more than 0 and at most 360 degrees (got 400)"},
      {{"--step", "nan", "-o", file}, 2, "--step must be more than 0 and at most 360 degrees (got undefined)"},
      {{"--paper", "foo", "-o", file}, 2, "--paper must be a4 or letter (got 'foo')"},
      {{"--rates", "rpm", "-o", file}, 2, "--rates must be rad (rad/s, rad/s²) or deg (deg/s, deg/s²) (got 'rpm')"},
      {{"--angles", "grad", "-o", file}, 2, "--angles must be deg or rad (got 'grad')"},
      {{"--step", "1e-9", "-o", file}, 2, "the table step 1e-09 gives more than 10000 rows"},
      {{"--step", "0.001", "-o", file}, 2, "a report's step must be at least 0.0360036"},
      {{"--at", "10,20", "-o", file}, 2, "--at takes one value"},
      {{}, 2, "report needs -o FILE.pdf"},
      {{"-o", (dir / "missing" / "r.pdf").string()}, 1, "cannot write " + (dir / "missing" / "r.pdf").string()},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"report", "--example", "thesis-crank-rocker"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto run = runCliCommand(args);
    INFO(run.err);
    CHECK(run.code == c.code);
    CHECK_THAT(run.err, Catch::Contains(c.message));
    CHECK(fs::is_empty(dir));
  }
  fs::remove_all(dir);
}

TEST_CASE("report refuses an input the linkage cannot reach", "[cli][report][errors]") {
  const fs::path dir = scratchDir("report-cli");
  // Frame 60, crank 40, coupler 30, rocker 25: at crank 180° B is 100 from O4, more than 30 + 25.
  const auto run = runCliCommand({"report", "--fourbar", "60,40,30,25", "--at", "180", "-o", (dir / "r.pdf").string()});
  CHECK(run.code == 3);
  CHECK_THAT(run.err, Catch::Contains("cannot be assembled at crank angle 180°"));
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}
