// analyze on a time base (--law): the CSV starts with time_s, the crank's angle, ω and α are
// the law's at each instant (a cycloidal rise's peak acceleration 2πh/T² among them), a
// measured θ(t) table drives it as the polynomial it samples, and bad law options are refused
// with the option named.

#include "tests/cli/run_cli.h"

#include "kinematics/design/design.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using linkwright::test::runCliCommand;
using linkwright::test::within;
namespace k = linkwright::kinematics;

namespace {

// The CSV's rows as numbers (empty cells as NaN), after checking the header starts with `head`.
std::vector<std::vector<double>> rowsOf(const std::string& csv, const std::string& head) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line.rfind(head, 0) == 0);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(cell.empty() || cell == "\r" ? NAN : std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

constexpr const char* kHead = "time_s,crank_angle_deg,crank_omega_rad_s,crank_alpha_rad_s2,";

}  // namespace

TEST_CASE("analyze --law cycloidal: the crank rises as the law says, peak α 2πh/T²", "[cli][law]") {
  // 90° in 0.5 s from 10°, sampled every 0.125 s: t = T/4 is the peak.
  const auto r = runCliCommand({"analyze", "--fourbar", "60,25,70,45", "--law", "cycloidal", "--rise", "90",
                                "--duration", "0.5", "--from", "10", "--step-time", "0.125"});
  REQUIRE(r.code == 0);
  const auto rows = rowsOf(r.out, kHead);
  REQUIRE(rows.size() == 5);
  const double h = k::degToRad(90.0), T = 0.5;
  CHECK(rows[0][0] == 0.0);
  CHECK(rows[0][1] == within(10.0, 1e-12));
  CHECK(rows[4][1] == within(100.0, 1e-12));
  CHECK(rows[1][3] == within(2.0 * k::kPi * h / (T * T), 1e-12));
  CHECK(rows[2][2] == within(2.0 * h / T, 1e-12));
  CHECK(rows[0][2] == 0.0);
  CHECK(rows[4][2] == 0.0);
}

TEST_CASE("analyze --law table: a measured θ(t) drives the crank as the cubic it samples", "[cli][law]") {
  const auto q = [](double t) { return 20.0 + 40.0 * t + 15.0 * t * t - 4.0 * t * t * t; };  // degrees
  const auto dq = [](double t) { return 40.0 + 30.0 * t - 12.0 * t * t; };
  const auto ddq = [](double t) { return 30.0 - 24.0 * t; };
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_law_table_test.csv").string();
  {
    std::ofstream f(path);
    f << "time_s,crank_angle_deg\n";
    for (const double t : {0.0, 0.2, 0.5, 0.7, 1.0, 1.3, 1.5, 2.0}) f << t << "," << q(t) << "\n";
  }
  const auto r = runCliCommand({"analyze", "--fourbar", "60,25,70,45", "--law-table", path, "--samples", "9"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto rows = rowsOf(r.out, kHead);
  REQUIRE(rows.size() == 9);
  for (const auto& row : rows) {
    const double t = row[0];
    CAPTURE(t);
    CHECK(row[1] == within(q(t), 1e-10));
    CHECK(row[2] == within(k::degToRad(dq(t)), 1e-10));
    CHECK(row[3] == within(k::degToRad(ddq(t)), 1e-9));
  }
  CHECK(rows.back()[0] == 2.0);
  std::filesystem::remove(path);
}

TEST_CASE("bad law options are refused with the option named", "[cli][law][errors]") {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--law", "cycloidal", "--rise", "90"}, "--law cycloidal needs --rise DEG and --duration S"},
      {{"--law", "ramp"}, "--law ramp needs --ramp-time S"},
      {{"--law", "jerk"}, "--law must be constant, ramp, cycloidal, 345 or table (got 'jerk')"},
      {{"--ramp-time", "2"}, "need --law"},
      {{"--law", "constant", "--to", "90"}, "--to sets the angle grid"},
      {{"--law", "constant", "--alpha", "1"}, "--alpha sets the angle grid"},
      {{"--law", "ramp", "--ramp-time", "-1"}, "--ramp-time"},
      {{"--law", "constant", "--omega", "0"}, "--to-time is needed"},
      {{"--law", "constant", "--from-time", "2", "--to-time", "1"}, "--to-time must not be before --from-time"},
      {{"--law", "cycloidal", "--rise", "90", "--duration", "1e-7"}, "law peak velocity"},
      {{"--law-table", "/nonexistent/theta.csv"}, "cannot be opened for reading"},
  };
  for (const auto& [extra, message] : cases) {
    std::vector<std::string> args{"analyze", "--fourbar", "60,25,70,45"};
    args.insert(args.end(), extra.begin(), extra.end());
    CAPTURE(extra);
    const auto r = runCliCommand(args);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK(r.out.empty());
  }
}

TEST_CASE("a document whose crank follows a law is analysed on its time base", "[cli][law][document]") {
  k::Design d = *k::designForExample("thesis-crank-rocker");
  d.samples = 31;
  d.time = k::TimeBase{k::RampToSpeed{0.0, k::rpmToRadPerSec(10.0), 2.0}, 0.0, 3.0};
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_law_document.linkwright").string();
  {
    std::ofstream f(path);
    f << k::io::writeDocument(d);
  }
  // The same table as the options that describe the same law.
  const auto fromFile = runCliCommand({"analyze", path});
  const auto fromOptions = runCliCommand({"analyze", "--example", "thesis-crank-rocker", "--law", "ramp", "--ramp-time",
                                          "2", "--to-time", "3", "--samples", "31"});
  INFO(fromFile.err);
  REQUIRE(fromFile.code == 0);
  REQUIRE(fromOptions.code == 0);
  CHECK(fromFile.out == fromOptions.out);
  CHECK(rowsOf(fromFile.out, kHead).size() == 31);
  CHECK(runCliCommand({"analyze", path, "--samples", "4"}).out.size() < fromFile.out.size());
  // The angle grid's options do not apply to it; extremes refine in time.
  const auto to = runCliCommand({"analyze", path, "--to", "90"});
  CHECK(to.code == 2);
  CHECK_THAT(to.err, Catch::Contains("--to does not apply: this linkage's driver follows a motion law in time"));
  const auto extremes = runCliCommand({"extremes", path});
  CHECK(extremes.code == 0);
  CHECK_THAT(extremes.out, Catch::StartsWith("extremes over times 0 s to 3 s, refined between 31 samples"));
  std::filesystem::remove(path);
}

TEST_CASE("a document's table law with lists of different lengths says so, with both lengths",
          "[cli][law][document][errors]") {
  k::Design d = *k::designForExample("thesis-crank-rocker");
  d.time = k::TimeBase{k::makeTableLaw({0.0, 0.3, 0.7, 1.2, 2.0}, {0.0, 0.1, 0.35, 0.9, 1.7}).value(), 0.0, 2.0};
  std::string text = k::io::writeDocument(d);
  const std::string full = "\"angle_rad\": [0, 0.1, 0.35, 0.9, 1.7]";
  REQUIRE(text.find(full) != std::string::npos);
  text.replace(text.find(full), full.size(), "\"angle_rad\": [0, 0.1, 0.35, 0.9]");
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_law_lists.linkwright").string();
  {
    std::ofstream f(path);
    f << text;
  }
  const auto r = runCliCommand({"analyze", path});
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  // It said "needs at least four rows of time and position (got 5)".
  CHECK_THAT(r.err, Catch::Contains("driver.law.angle_rad has 4 values but driver.law.time_s has 5: the two lists "
                                    "must have the same length, one value per time"));
  std::filesystem::remove(path);
}

TEST_CASE("extremes on a time base are refined in time: a cycloidal rise's peak α at T/4", "[cli][law][extremes]") {
  // Sampled every 0.07 s, so no sample lands on T/4 = 0.125 s: the search finds it.
  const auto r = runCliCommand({"extremes", "--fourbar", "60,25,70,45", "--law", "cycloidal", "--rise", "90",
                                "--duration", "0.5", "--step-time", "0.07"});
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  std::string line;
  bool found = false;
  while (std::getline(lines, line)) {
    if (line.rfind("crank_alpha_rad_s2", 0) != 0) continue;
    std::istringstream cells(line.substr(std::string("crank_alpha_rad_s2").size()));
    double minimum = 0, minimumAt = 0, maximum = 0, maximumAt = 0;
    cells >> minimum >> minimumAt >> maximum >> maximumAt;
    const double peak = 2.0 * k::kPi * k::degToRad(90.0) / (0.5 * 0.5);
    CHECK(maximum == within(peak, 1e-7 * peak));  // printed to 9 digits
    CHECK(maximumAt == within(0.125, 1e-6));      // printed to 6 decimals
    CHECK(minimum == within(-peak, 1e-7 * peak));
    CHECK(minimumAt == within(0.375, 1e-6));
    found = true;
  }
  CHECK(found);
}
