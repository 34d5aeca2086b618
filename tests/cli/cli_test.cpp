// linkwright-cli run in-process through runCli: options, exit codes, messages, and the CSV it
// writes compared with the core's own solution at every row.

#include "app/cli/cli.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using namespace linkwright;

struct Run {
  int code = -1;
  std::string out;
  std::string err;
};

Run run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  Run r;
  r.code = cli::runCli(args, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// A parsed CSV: header names and numeric rows.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return static_cast<std::size_t>(it - header.begin());
  }
  double value(std::size_t row, const std::string& name) const { return std::stod(rows[row][column(name)]); }
};

Table parseCsv(const std::string& text) {
  Table t;
  const auto lines = splitLines(text);
  REQUIRE_FALSE(lines.empty());
  t.header = splitCells(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) t.rows.push_back(splitCells(lines[i]));
  return t;
}

} // namespace

TEST_CASE("help and version succeed and document the exit codes", "[cli]") {
  const Run help = run({"--help"});
  CHECK(help.code == 0);
  CHECK(help.out.find("Exit codes:") != std::string::npos);
  CHECK(help.out.find("3  the linkage cannot be assembled") != std::string::npos);
  CHECK(help.out.find("--fourbar FRAME,CRANK,COUPLER,ROCKER") != std::string::npos);
  const Run analyzeHelp = run({"analyze", "--help"});
  CHECK(analyzeHelp.code == 0);
  CHECK(analyzeHelp.out.find("--coupler-point") != std::string::npos);
  const Run version = run({"--version"});
  CHECK(version.code == 0);
  CHECK(version.out.rfind("linkwright-cli ", 0) == 0);
}

TEST_CASE("bad usage exits 2 with a message naming the option and the reason", "[cli][errors]") {
  using Args = std::vector<std::string>;
  auto [args, expected] = GENERATE(table<Args, std::string>({
      {Args{}, "missing command"},
      {Args{"frobnicate"}, "unknown command 'frobnicate'"},
      {Args{"--frobnicate"}, "unknown option '--frobnicate'"},
      {Args{"analyze", "--example", "thesis-crank-rocker", "--speed", "3"}, "unknown option '--speed' for 'analyze'"},
      {Args{"classify", "--example", "thesis-crank-rocker", "--rpm", "3"}, "unknown option '--rpm' for 'classify'"},
      {Args{"analyze", "--example", "thesis-crank-rocker", "stray"}, "unexpected argument 'stray'"},
      {Args{"analyze", "--example"}, "--example needs a value"},
      {Args{"analyze", "--example", "nope"}, "no example named 'nope'"},
      {Args{"analyze"}, "needs --fourbar FRAME,CRANK,COUPLER,ROCKER or --example NAME"},
      {Args{"analyze", "--fourbar", "60,25,70"}, "--fourbar expects FRAME,CRANK,COUPLER,ROCKER (got '60,25,70')"},
      {Args{"analyze", "--fourbar", "60,25,x,45"}, "--fourbar: 'x' is not a number"},
      {Args{"analyze", "--fourbar", "0,25,70,45"}, "--fourbar: frame length must be positive and finite (got 0)"},
      {Args{"analyze", "--fourbar", "60,-25,70,45"}, "--fourbar: crank length must be positive and finite (got -25)"},
      {Args{"analyze", "--fourbar", "60,25,nan,45"}, "--fourbar: coupler length must be positive and finite (got nan)"},
      {Args{"analyze", "--fourbar", "60,25,70,inf"}, "--fourbar: rocker length must be positive and finite (got inf)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "fast"}, "--rpm: 'fast' is not a number"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "nan"}, "--rpm must be finite (got nan)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--omega", "inf"}, "--omega must be finite (got inf)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--alpha", "-inf"}, "--alpha must be finite (got -inf)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "1", "--omega", "1"}, "--rpm and --omega cannot be used together"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "0"}, "--step must be positive (got 0)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "-5"}, "--step must be positive (got -5)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "1e-9"}, "--step is too small"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "1", "--samples", "5"}, "--step and --samples cannot be used together"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--samples", "0"}, "--samples must be between 1 and"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--samples", "2.5"}, "--samples: '2.5' is not a whole number"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--from", "90", "--to", "10"}, "--to must not be less than --from"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--branch", "up"}, "--branch must be 'open' or 'crossed' (got 'up')"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--coupler-point", "1"}, "--coupler-point expects U,V"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--coupler-point", "1,nan"}, "coupler point across must be finite (got nan)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "1", "--rpm", "2"}, "--rpm is given more than once"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--unit", "m/s"}, "--unit must be a unit name made of letters"},
      {Args{"classify", "--example", "thesis-crank-rocker", "--json=yes"}, "--json takes no value"},
  }));
  CAPTURE(args);
  const Run r = run(args);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(expected));
}

TEST_CASE("options accept --name=value and numbers ignore the locale", "[cli]") {
  std::locale::global(std::locale::classic());
  const Run a = run({"analyze", "--fourbar=60,25,70,45", "--rpm=10", "--step=30"});
  const Run b = run({"analyze", "--fourbar", "60,25,70,45", "--rpm", "10", "--step", "30"});
  REQUIRE(a.code == 0);
  CHECK(a.out == b.out);
}

TEST_CASE("analyze writes the thesis table: every row equals the core's solution", "[cli][published]") {
  const Run r = run({"analyze", "--example", "thesis-crank-rocker"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  const Table t = parseCsv(r.out);
  REQUIRE(t.rows.size() == 13);  // 0° to 360° every 30°, as the thesis prints it
  const auto mechanism = kinematics::makeFourBar({60, 25, 70, 45}, kinematics::Branch::Open);
  REQUIRE(mechanism.ok());
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    const double crankDeg = t.value(row, "crank_angle_deg");
    CAPTURE(crankDeg);
    CHECK(crankDeg == 30.0 * static_cast<double>(row));
    const auto pose = kinematics::solvePose(*mechanism, {kinematics::degToRad(crankDeg), kinematics::rpmToRadPerSec(10), 0});
    REQUIRE(pose.ok());
    using kinematics::fourbar::kCoupler;
    using kinematics::fourbar::kRocker;
    // The CSV holds round-trip doubles; the unwrapped angle equals the pose's up to whole turns.
    CHECK(t.value(row, "coupler_omega_rad_s") == pose->linkOmega[kCoupler.index]);
    CHECK(t.value(row, "rocker_alpha_rad_s2") == pose->linkAlpha[kRocker.index]);
    CHECK(std::remainder(kinematics::degToRad(t.value(row, "rocker_angle_deg")) - pose->linkAngle[kRocker.index],
                         2 * kinematics::kPi) == Approx(0).margin(1e-12));
  }
  // Spot check against the thesis's printed 90° row (Table 7: 16.10°, 80.72°, 0.07, 0.62, 0.16 rad/s²).
  CHECK(t.value(3, "coupler_angle_deg") == Approx(16.10).margin(0.005));
  CHECK(t.value(3, "rocker_angle_deg") == Approx(80.72).margin(0.005));
  CHECK(t.value(3, "coupler_omega_rad_s") == Approx(0.07).margin(0.005));
  CHECK(t.value(3, "rocker_omega_rad_s") == Approx(0.62).margin(0.005));
  CHECK(t.value(3, "coupler_alpha_rad_s2") == Approx(0.16).margin(0.005));
}

TEST_CASE("analyze reproduces the Alvi rows on both branches", "[cli][published]") {
  // Alvi et al. at 40°: open (second printed row) 103.82°, 38.99°; crossed −126.30°, −61.47°.
  const Run open = run({"analyze", "--example", "alvi-fourbar", "--from", "40", "--to", "40"});
  const Run crossed = run({"analyze", "--example", "alvi-fourbar", "--from", "40", "--to", "40", "--branch", "crossed"});
  REQUIRE(open.code == 0);
  REQUIRE(crossed.code == 0);
  const Table o = parseCsv(open.out);
  const Table c = parseCsv(crossed.out);
  REQUIRE(o.rows.size() == 1);
  CHECK(o.value(0, "rocker_angle_deg") == Approx(103.82).margin(0.005));
  CHECK(o.value(0, "coupler_angle_deg") == Approx(38.99).margin(0.005));
  CHECK(o.value(0, "rocker_omega_rad_s") == Approx(0.07).margin(0.005));
  CHECK(c.value(0, "rocker_angle_deg") == Approx(-126.30).margin(0.005));
  CHECK(c.value(0, "coupler_angle_deg") == Approx(-61.47).margin(0.005));
  CHECK(c.value(0, "coupler_alpha_rad_s2") == Approx(50.99).margin(0.005));
}

TEST_CASE("angles stay continuous over a full turn of a double-crank", "[cli]") {
  const Run r = run({"analyze", "--fourbar", "20,60,70,65", "--samples", "721"});
  REQUIRE(r.code == 0);
  const Table t = parseCsv(r.out);
  REQUIRE(t.rows.size() == 721);
  for (std::size_t row = 1; row < t.rows.size(); ++row)
    CHECK(std::abs(t.value(row, "rocker_angle_deg") - t.value(row - 1, "rocker_angle_deg")) < 5.0);
  // The rocker of a drag link turns once with the crank: +360° over the sweep.
  CHECK(t.value(720, "rocker_angle_deg") - t.value(0, "rocker_angle_deg") == Approx(360.0).margin(1e-9));
}

TEST_CASE("a range that cannot be fully assembled exits 3 and keeps the rows that can", "[cli][errors]") {
  // Non-Grashof 40/30/20/25: the crank can reach only |θ| ≤ 78.58°.
  const Run r = run({"analyze", "--fourbar", "40,30,20,25", "--from", "0", "--to", "180", "--step", "10"});
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("cannot be assembled at 11 of 19 requested crank angles (80° to 180°)"));
  CHECK_THAT(r.err, Catch::Contains("B and O4 are"));
  CHECK_THAT(r.err, Catch::Contains("more than coupler + rocker = 45 mm"));
  CHECK_THAT(r.err, Catch::Contains("-78.5848° to 78.5848° (exact)"));
  const Table t = parseCsv(r.out);
  REQUIRE(t.rows.size() == 8);
  CHECK(t.value(7, "crank_angle_deg") == 70.0);
}

TEST_CASE("a linkage that never closes: classify says so and exits 3", "[cli][errors]") {
  const Run r = run({"classify", "--fourbar", "100,10,20,30"});
  CHECK(r.code == 3);
  CHECK_THAT(r.out, Catch::Contains("none: the loop never closes"));
  CHECK_THAT(r.err, Catch::Contains("cannot be assembled at any crank angle"));
}

TEST_CASE("classify reports the thesis crank-rocker", "[cli]") {
  const Run r = run({"classify", "--example", "thesis-crank-rocker"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("crank-rocker (shortest link: crank, longest: coupler)"));
  CHECK_THAT(r.out, Catch::Contains("95 mm, 105 mm"));
  CHECK_THAT(r.out, Catch::Contains("= 1"));
  // The thesis's γ column: 25.21° at θ2 = 0°, 92.73° at 180°.
  CHECK_THAT(r.out, Catch::Contains("min 25.21° at crank 0.00°, max 92.73° at crank 180.00°"));
  CHECK_THAT(r.out, Catch::Contains("time ratio"));
}

TEST_CASE("analyze -o writes the same CSV to a file, atomically", "[cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "linkwright_cli_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "thesis.csv";
  std::filesystem::remove(file);
  const Run toFile = run({"analyze", "--example", "thesis-crank-rocker", "-o", file.string()});
  REQUIRE(toFile.code == 0);
  CHECK(toFile.out.empty());
  std::ifstream in(file, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == run({"analyze", "--example", "thesis-crank-rocker"}).out);
  CHECK_FALSE(std::filesystem::exists(dir / "thesis.csv.linkwright-tmp"));

  const Run bad = run({"analyze", "--example", "thesis-crank-rocker", "-o", (dir / "missing" / "x.csv").string()});
  CHECK(bad.code == 1);
  CHECK_THAT(bad.err, Catch::Contains("cannot write"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("examples lists every built-in example", "[cli]") {
  const Run r = run({"examples"});
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("thesis-crank-rocker"));
  CHECK_THAT(r.out, Catch::Contains("alvi-fourbar"));
  CHECK_THAT(r.out, Catch::Contains("--fourbar 60,25,70,45"));
}

TEST_CASE("extremes refines the LS3 piston's peak speed and acceleration (seed 003)", "[cli][extremes]") {
  const Run r = run({"extremes", "--example", "ls3-engine", "--step", "30"});
  REQUIRE(r.code == 0);
  // Seed 003 (SolidWorks, 110 Hz): 33.17 m/s and 28497.18 m/s²; exact: 33.1744 m/s and
  // rω²(1 + r/L) = 28499.58 m/s², found here from samples 30° apart.
  std::istringstream lines(r.out);
  bool sawSpeed = false, sawAcceleration = false;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::string name;
    double minimum = 0, minAt = 0, maximum = 0, maxAt = 0;
    cells >> name >> minimum >> minAt >> maximum >> maxAt;
    if (name == "C_vx_mm_s") {
      sawSpeed = true;
      CHECK(maximum / 1000.0 == Approx(33.1744).epsilon(1e-5));
      CHECK(minimum == Approx(-maximum).epsilon(1e-9));
    }
    if (name == "C_ax_mm_s2") {
      sawAcceleration = true;
      const double omega = 2.0 * kinematics::kPi * 110.0;
      CHECK(-minimum == Approx(46.0 * omega * omega * (1.0 + 46.0 / (6.098 * 25.4))).epsilon(1e-8));
    }
  }
  CHECK(sawSpeed);
  CHECK(sawAcceleration);
}

TEST_CASE("slider-crank examples analyze, and classify says it is for four-bars", "[cli]") {
  const Run analyze = run({"analyze", "--example", "ls3-engine", "--step", "90"});
  REQUIRE(analyze.code == 0);
  CHECK_THAT(analyze.out, Catch::StartsWith("crank_angle_deg,crank_omega_rad_s,crank_alpha_rad_s2,rod_angle_deg"));
  CHECK(parseCsv(analyze.out).rows.size() == 5);
  const Run classify = run({"classify", "--example", "ls3-engine"});
  CHECK(classify.code == 2);
  CHECK_THAT(classify.err, Catch::Contains("is not a four-bar but a slider-crank; classify works on four-bars and shapers"));
  const Run point = run({"analyze", "--example", "ls3-engine", "--coupler-point", "1,2"});
  CHECK(point.code == 2);
  CHECK_THAT(point.err, Catch::Contains("--coupler-point applies to four-bars"));
  CHECK_THAT(run({"examples"}).out, Catch::Contains("ls3-engine"));
}

TEST_CASE("classify gives the shaper's exact time ratio and stroke", "[cli][shaper]") {
  // Seed 003 reads a time ratio of "2" off a graph; with r/d = 100/203.96 it is exactly
  // (π + 2 asin(r/d)) / (π − 2 asin(r/d)) = 1.9683.
  const Run r = run({"classify", "--example", "shaper"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("time ratio           1.9683 (slow stroke 238.72°, quick stroke 121.28°"));
  CHECK_THAT(r.out, Catch::Contains("= 1"));
  const Run json = run({"classify", "--example", "shaper", "--json"});
  REQUIRE(json.code == 0);
  CHECK_THAT(json.out, Catch::Contains("\"time_ratio\": 1.968"));
}
