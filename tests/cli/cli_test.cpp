// linkwright-cli run in-process through runCli: options, exit codes, messages, and the CSV it
// writes compared with the core's own solution at every row.

#include "app/cli/cli.h"
#include "app/cli/text_table.h"
#include "tests/cli/run_cli.h"
#include "tests/support/file_size_limit.h"

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace {

using namespace linkwright;

using Run = test::CliRun;
Run run(const std::vector<std::string>& args) { return test::runCliCommand(args); }

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

}  // namespace

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

// A standard output that cannot be written (`> /dev/full`, a full disk) fails every command
// with exit 1 and a sentence; the results are incomplete and must not look finished.
TEST_CASE("a standard output that cannot be written exits 1, whatever the command", "[cli][errors]") {
  using Args = std::vector<std::string>;
  const Args args =
      GENERATE(Args{"analyze", "--example", "watt-ii", "--samples", "20"}, Args{"extremes", "--example", "watt-ii"},
               Args{"classify", "--example", "watt-ii"}, Args{"machine", "--example", "funsho-fourbar", "--cs", "0.05"},
               Args{"arm", "--example", "seed-arm"}, Args{"inversions", "--example", "funsho-fourbar"},
               Args{"accuracy", "--example", "watt-ii"}, Args{"examples"}, Args{"--help"});
  CAPTURE(args);
  std::ostream unwritable(nullptr);  // every write fails, as on a full disk
  std::ostringstream err;
  CHECK(cli::runCli(args, unwritable, err) == 1);
  CHECK(err.str().find("cannot write the standard output") != std::string::npos);
  // The same command with a working output succeeds, so the failure is the output's.
  CHECK(run(args).code == 0);
}

TEST_CASE("bad usage exits 2 with a message naming the option and the reason", "[cli][errors]") {
  using Args = std::vector<std::string>;
  auto [args, expected] = GENERATE(table<Args, std::string>({
      {Args{}, "missing command"},
      {Args{"frobnicate"}, "unknown command 'frobnicate'"},
      {Args{"--frobnicate"}, "unknown option '--frobnicate'"},
      {Args{"analyze", "--example", "thesis-crank-rocker", "--speed", "3"}, "unknown option '--speed' for 'analyze'"},
      {Args{"classify", "--example", "thesis-crank-rocker", "--rpm", "3"}, "unknown option '--rpm' for 'classify'"},
      {Args{"analyze", "--example", "thesis-crank-rocker", "stray"},
       "--example cannot be used with a document (stray)"},
      {Args{"analyze", "--example"}, "--example needs a value"},
      {Args{"analyze", "--example", "nope"}, "no example named 'nope'"},
      {Args{"analyze"}, "needs FILE.json, --fourbar FRAME,CRANK,COUPLER,ROCKER or --example NAME"},
      {Args{"analyze", "--fourbar", "60,25,70"}, "--fourbar expects FRAME,CRANK,COUPLER,ROCKER (got '60,25,70')"},
      {Args{"analyze", "--fourbar", "60,25,x,45"}, "--fourbar: 'x' is not a number"},
      {Args{"analyze", "--fourbar", "0,25,70,45"}, "--fourbar: frame length must be positive and finite (got 0)"},
      {Args{"analyze", "--fourbar", "60,-25,70,45"}, "--fourbar: crank length must be positive and finite (got -25)"},
      {Args{"analyze", "--fourbar", "60,25,nan,45"},
       "--fourbar: coupler length must be positive and finite (got undefined)"},
      {Args{"analyze", "--fourbar", "60,25,70,inf"},
       "--fourbar: rocker length must be positive and finite (got undefined)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "fast"}, "--rpm: 'fast' is not a number"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "nan"},
       "--rpm must be finite and within ±9549296 rev/min, which is 1e6 rad/s (got undefined)"},
      // polygon's --rpm in rev/min, as analyze's, not converted to rad/s before it is checked.
      {Args{"polygon", "--example", "thesis-crank-rocker", "--at", "30", "--rpm", "1e12"},
       "--rpm must be finite and within ±9549296 rev/min, which is 1e6 rad/s (got 1e+12)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--omega", "inf"},
       "--omega must be finite and within ±1e6 rad/s (got undefined)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--alpha", "-inf"},
       "--alpha must be finite and within ±1e12 rad/s² (got undefined)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--rpm", "1", "--omega", "1"},
       "--rpm and --omega cannot be used together"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "0"}, "--step must be positive (got 0)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "-5"}, "--step must be positive (got -5)"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "1e-9"}, "--step is too small"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--step", "1", "--samples", "5"},
       "--step and --samples cannot be used together"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--samples", "0"}, "--samples must be between 1 and"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--samples", "2.5"}, "--samples: '2.5' is not a whole number"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--from", "90", "--to", "10"}, "--to must not be less than --from"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--branch", "up"},
       "--branch must be 'open' or 'crossed' (got 'up')"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--coupler-point", "1"}, "--coupler-point expects U,V"},
      {Args{"analyze", "--fourbar", "60,25,70,45", "--coupler-point", "1,nan"},
       "coupler point across must be finite (got undefined)"},
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
    const auto pose =
        kinematics::solvePose(*mechanism, {kinematics::degToRad(crankDeg), kinematics::rpmToRadPerSec(10), 0});
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
  const Run crossed =
      run({"analyze", "--example", "alvi-fourbar", "--from", "40", "--to", "40", "--branch", "crossed"});
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
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);

  const Run bad = run({"analyze", "--example", "thesis-crank-rocker", "-o", (dir / "missing" / "x.csv").string()});
  CHECK(bad.code == 1);
  CHECK_THAT(bad.err, Catch::Contains("cannot write"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a device or a folder as an input file is refused before reading, exit 2", "[cli][errors]") {
  // Was: analyze /dev/zero and compare … /dev/zero grew by 0.7 GB/s until the kernel killed them.
  const Run document = run({"analyze", "/dev/zero"});
  CHECK(document.code == 2);
  CHECK_THAT(document.err,
             Catch::Contains("/dev/zero: cannot be read as a Linkwright document: it is not a regular file"));
  const Run table = run({"compare", "--example", "thesis-crank-rocker", "/dev/zero", "--map", "auto"});
  CHECK(table.code == 2);
  CHECK_THAT(table.err, Catch::Contains("/dev/zero: cannot be read as a table: it is not a regular file"));
  const Run folder = run({"analyze", std::filesystem::temp_directory_path().string()});
  CHECK(folder.code == 2);
  CHECK_THAT(folder.err, Catch::Contains("it is a folder"));
  const Run law = run({"analyze", "--example", "thesis-crank-rocker", "--law", "table", "--law-table", "/dev/zero"});
  CHECK(law.code == 2);
  CHECK_THAT(law.err, Catch::Contains("--law-table /dev/zero: cannot be read as a table"));
}

TEST_CASE("writing -o to a device or a symlink goes through it, never replacing it", "[cli][errors]") {
  // Was: every writer renamed a temporary file over the target, so -o /dev/null failed (and as
  // root replaced the system's /dev/null) and -o link replaced the link.
  const Run null = run({"analyze", "--example", "thesis-crank-rocker", "-o", "/dev/null"});
  CHECK(null.code == 0);
  CHECK(std::filesystem::is_character_file("/dev/null"));
  const auto dir = std::filesystem::temp_directory_path() / "linkwright_cli_link_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::create_symlink("real.csv", dir / "link.csv");
  REQUIRE(run({"analyze", "--example", "thesis-crank-rocker", "-o", (dir / "link.csv").string()}).code == 0);
  CHECK(std::filesystem::is_symlink(dir / "link.csv"));
  CHECK(std::filesystem::file_size(dir / "real.csv") > 1000);
  for (const char* command : {"dxf", "report"}) {
    CAPTURE(command);
    const Run r = run({command, "--example", "thesis-crank-rocker", "-o", "/dev/null"});
    CHECK(r.code == 0);
    CHECK(std::filesystem::is_character_file("/dev/null"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("analyze -o to a full disk keeps the previous file and says why", "[cli][errors]") {
  const auto dir = std::filesystem::temp_directory_path() / "linkwright_cli_full_disk_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto file = dir / "thesis.csv";
  REQUIRE(run({"analyze", "--example", "thesis-crank-rocker", "--step", "90", "-o", file.string()}).code == 0);
  const auto before = std::filesystem::file_size(file);
  Run full;
  {
    test::FileSizeLimit limit(100);  // smaller than the table: the write fails part-way
    full = run({"analyze", "--example", "thesis-crank-rocker", "--step", "30", "-o", file.string()});
  }
  CHECK(full.code == 1);
  CHECK_THAT(full.err, Catch::Contains("cannot write " + file.string() + ": File too large"));
  CHECK(std::filesystem::file_size(file) == before);
  // No temporary file left beside it.
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
  // The DXF reported success and left a cut-off file over the old one (its last buffer was
  // written at close, unchecked).
  const auto drawing = dir / "links.dxf";
  REQUIRE(run({"dxf", "--example", "thesis-crank-rocker", "-o", drawing.string()}).code == 0);
  const std::string old = [&] {
    std::ifstream in(drawing, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  Run dxf;
  {
    test::FileSizeLimit limit(old.size() - 100);
    dxf = run({"dxf", "--example", "thesis-crank-rocker", "--at", "30", "-o", drawing.string()});
  }
  CHECK(dxf.code == 1);
  CHECK_THAT(dxf.err, Catch::Contains("cannot write " + drawing.string() + ": File too large"));
  std::ifstream in(drawing, std::ios::binary);
  CHECK(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()) == old);
  std::filesystem::remove_all(dir);
}

TEST_CASE("values outside the input domain exit 2 naming the option, the value and the range",
          "[cli][errors][domain]") {
  // The issue's reports: each printed nan or inf, or ran for 20 s, before the domain.
  auto [args, message] = GENERATE(table<std::vector<std::string>, std::string>({
      {{"analyze", "--fourbar", "60,25,70,45", "--omega", "1e160", "--step", "90"},
       "--omega must be finite and within ±1e6 rad/s (got 1e+160)"},
      {{"analyze", "--fourbar", "1e308,25,70,45"}, "--fourbar: frame length must be between 1e-6 and 1e9 (got 1e+308)"},
      {{"extremes", "--fourbar", "60,25,70,45", "--rpm", "1e200"},
       "--rpm must be finite and within ±9549296 rev/min, which is 1e6 rad/s (got 1e+200)"},
      {{"analyze", "--fourbar", "1e9,1e-6,1e9,1e9"}, "lengths span too wide a range: link crank is 1e-06 mm but"},
      {{"analyze", "--fourbar", "60,25,70,45", "--alpha", "2e12"},
       "--alpha must be finite and within ±1e12 rad/s² (got 2e+12)"},
      {{"analyze", "--fourbar", "60,25,70,45", "--from", "-2e6"},
       "--from must be finite and within ±1e6 degrees (got -2e+06)"},
      {{"arm", "--arm", "0.3,0.2", "--from-point", "0.3,0", "--to-point", "0.7,0", "--speed", "1e10"},
       "--speed: speed must be finite and within ±1e9 length units/s (got 1e+10)"},
  }));
  CAPTURE(args);
  const Run r = run(args);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(message));
}

TEST_CASE("the bound of --rpm is stated in rev/min, and every speed within it is accepted", "[cli][errors][domain]") {
  // 1e6 rad/s is 9549296.6 rev/min: the message said "within ±9.55e+06 rev/min" and refused 9.55e6.
  const Run over = run({"analyze", "--fourbar", "60,25,70,45", "--rpm", "9.55e6", "--step", "90"});
  CHECK(over.code == 2);
  CHECK(over.err ==
        "linkwright-cli: --rpm must be finite and within ±9549296 rev/min, which is 1e6 rad/s (got 9550000)\n");
  for (const char* rpm : {"9549296", "-9549296"}) {
    CAPTURE(rpm);
    CHECK(run({"analyze", "--fourbar", "60,25,70,45", "--rpm", rpm, "--step", "90"}).code == 0);
  }
  const Run compare = run({"compare", "--example", "thesis-crank-rocker",
                           std::string(LINKWRIGHT_TEST_DATA) + "/compare/thesis_solidworks_fig41_angles.tsv", "--map",
                           "2=time:s,3=coupler_angle:deg,4=rocker_angle:deg:rev", "--rpm", "9.55e6"});
  CHECK(compare.code == 2);
  CHECK(compare.err == over.err);
}

TEST_CASE("the text table writes a value that is still not finite as undefined", "[cli][errors]") {
  // The last guard of --format table: whatever let a non-finite number into a sweep.
  const auto m = kinematics::makeFourBar({60, 25, 70, 45}, kinematics::Branch::Open).value();
  auto s = kinematics::sweep(m, {0.0, 1.0, 3, 1.0, 0.0}).value();
  s.linkAlpha[kinematics::fourbar::kRocker.index][1] = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream out;
  cli::writeSweepTable(out, m, s);
  CHECK(out.str().find("nan") == std::string::npos);
  CHECK(out.str().find("undefined") != std::string::npos);
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

TEST_CASE("slider-crank examples analyze and classify", "[cli]") {
  const Run analyze = run({"analyze", "--example", "ls3-engine", "--step", "90"});
  REQUIRE(analyze.code == 0);
  CHECK_THAT(analyze.out, Catch::StartsWith("crank_angle_deg,crank_omega_rad_s,crank_alpha_rad_s2,rod_angle_deg"));
  CHECK(parseCsv(analyze.out).rows.size() == 5);
  // The rod's transmission angle is worst (72.72° = acos(r/L)) with the crank at 90°.
  const Run classify = run({"classify", "--example", "ls3-engine"});
  CHECK(classify.code == 0);
  CHECK_THAT(classify.out,
             Catch::Contains("transmission at C    min 72.72° at crank 90.00°, max 90.00° at crank 0.00°"));
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

// ---- arm: the two-link arm of seed 004 along a straight tip path --------------------------

TEST_CASE("arm follows seed 004's line: every row equals the core's solution", "[cli][arm][published]") {
  const Run r = run({"arm", "--example", "seed-arm"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  const Table t = parseCsv(r.out);
  CHECK(t.header == std::vector<std::string>{"time_s", "tip_x_m", "tip_y_m", "upper_angle_deg", "forearm_angle_deg",
                                             "upper_omega_rad_s", "forearm_omega_rad_s", "upper_alpha_rad_s2",
                                             "forearm_alpha_rad_s2", "elbow_x_m", "elbow_y_m"});
  // The seed's elbow is "down" (its θ1 rises from −39° to 51°): the core's Crossed branch.
  const kinematics::TwoLinkArm arm{0.3, 0.2};
  const auto core = kinematics::followLine(arm, kinematics::Branch::Crossed, {{0.3, 0.0}, {0.0, 0.3}, 2.0}, 101);
  REQUIRE(core.ok());
  REQUIRE(t.rows.size() == 101);
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    const kinematics::ArmSample& s = core->samples[row];
    CAPTURE(row);
    REQUIRE(s.reachable);
    // The time column prints 12 significant digits (within 5e-12 relative, as analyze's angle
    // column). The tip is on the path at s = 2t, the joints from the linkage solver (arm is an
    // alias of analyze): equal to the closed form to round-off, and to 1e-12.
    CHECK(t.value(row, "time_s") == Approx(s.time).epsilon(1e-11));
    CHECK(t.value(row, "tip_x_m") == Approx(s.tip.x()).margin(1e-15));
    CHECK(t.value(row, "tip_y_m") == Approx(s.tip.y()).margin(1e-15));
    // Angles are unwrapped along the path: equal to the core's up to whole turns.
    for (const auto& [name, angle] :
         {std::pair{"upper_angle_deg", s.state.upperAngle}, {"forearm_angle_deg", s.state.forearmAngle}})
      CHECK(std::remainder(kinematics::degToRad(t.value(row, name)) - angle, 2 * kinematics::kPi) ==
            Approx(0).margin(1e-12));
    CHECK(t.value(row, "upper_omega_rad_s") == Approx(s.state.upperOmega).epsilon(1e-12));
    CHECK(t.value(row, "forearm_omega_rad_s") == Approx(s.state.forearmOmega).epsilon(1e-12));
    CHECK(t.value(row, "upper_alpha_rad_s2") == Approx(s.state.upperAlpha).epsilon(1e-12));
    CHECK(t.value(row, "forearm_alpha_rad_s2") == Approx(s.state.forearmAlpha).epsilon(1e-12));
    CHECK(t.value(row, "elbow_x_m") == Approx(s.state.elbow.x()).margin(1e-15));
    CHECK(t.value(row, "elbow_y_m") == Approx(s.state.elbow.y()).margin(1e-15));
  }
  // Closed form at the ends: the elbow angle off the tip line is acos(7/9) (|OB| = 0.3 m at
  // both ends), so θ1 goes from −38.94° to 90° − 38.94° = 51.06°, as the seed's plot shows.
  const double offLine = kinematics::radToDeg(std::acos(7.0 / 9.0));
  CHECK(t.value(0, "upper_angle_deg") == Approx(-offLine).epsilon(1e-13));
  CHECK(t.value(100, "upper_angle_deg") == Approx(90.0 - offLine).epsilon(1e-13));
  CHECK(t.value(100, "time_s") == Approx(0.3 * std::sqrt(2.0) / 2.0).epsilon(1e-11));
}

TEST_CASE("arm gives both elbow solutions: up is the core's open branch, mirrored by down", "[cli][arm]") {
  const Run up = run({"arm", "--example", "seed-arm", "--elbow", "up", "--samples", "11"});
  const Run down = run({"arm", "--example", "seed-arm", "--samples", "11"});
  REQUIRE(up.code == 0);
  REQUIRE(down.code == 0);
  const Table u = parseCsv(up.out), d = parseCsv(down.out);
  const auto core = kinematics::followLine({0.3, 0.2}, kinematics::Branch::Open, {{0.3, 0.0}, {0.0, 0.3}, 2.0}, 11);
  REQUIRE(core.ok());
  for (std::size_t row = 0; row < 11; ++row) {
    CAPTURE(row);
    CHECK(u.value(row, "forearm_omega_rad_s") == Approx(core->samples[row].state.forearmOmega).epsilon(1e-12));
    const Eigen::Vector2d tip(u.value(row, "tip_x_m"), u.value(row, "tip_y_m"));
    const Eigen::Vector2d eu(u.value(row, "elbow_x_m"), u.value(row, "elbow_y_m"));
    const Eigen::Vector2d ed(d.value(row, "elbow_x_m"), d.value(row, "elbow_y_m"));
    CHECK(kinematics::cross(tip, eu) > 0.0);  // up: counter-clockwise side of shoulder→tip
    CHECK(kinematics::cross(tip, ed) < 0.0);
    // Mirror images about the line shoulder→tip: reflecting one elbow gives the other.
    const Eigen::Vector2d axis = tip.normalized();
    CHECK((2.0 * eu.dot(axis) * axis - eu - ed).norm() < 1e-14);
  }
}

TEST_CASE("arm reports where the path leaves the workspace, exactly, and exits 3", "[cli][arm][errors]") {
  // Out along +x at 2 m/s from 0.3 m: beyond r1 + r2 = 0.5 m from t = 0.1 s to the end, 0.2 s.
  const Run r = run(
      {"arm", "--arm", "0.3,0.2", "--from-point", "0.3,0", "--to-point", "0.7,0", "--speed", "2", "--samples", "9"});
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("4 of 9 samples cannot be reached"));
  CHECK_THAT(r.err, Catch::Contains("unreachable for t = 0.1 s to 0.2 s (exact): tip from (0.5, 0) m to (0.7, 0) m"));
  CHECK_THAT(r.err, Catch::Contains("the arm is stretched out at t = 0.1 s, tip (0.5, 0) m"));
  CHECK(r.out.find("nan") == std::string::npos);
  const Table t = parseCsv(r.out);
  REQUIRE(t.rows.size() == 9);  // every time is listed; the unreachable ones with empty joint cells
  for (std::size_t row = 0; row < 9; ++row) {
    CAPTURE(row);
    CHECK_FALSE(t.rows[row][t.column("tip_x_m")].empty());
    CHECK(t.rows[row][t.column("upper_angle_deg")].empty() == (row > 4));
    CHECK(t.rows[row][t.column("elbow_y_m")].empty() == (row > 4));
    CHECK(t.rows[row][t.column("forearm_alpha_rad_s2")].empty() == (row >= 4));  // stretched at t = 0.1 s
  }
  // Through the hole |p| < r1 − r2 = 0.1 m at 1 m/s: from t = 0.3 ∓ √(0.1² − 0.05²) s.
  const Run hole =
      run({"arm", "--arm", "0.3,0.2", "--from-point", "-0.3,0.05", "--to-point", "0.3,0.05", "--speed", "1"});
  CHECK(hole.code == 3);
  CHECK_THAT(hole.err,
             Catch::Contains("unreachable for t = 0.213397 s to 0.386603 s (exact): tip from (-0.0866025, 0.05) m"));
  const Run table = run({"arm", "--arm", "0.3,0.2", "--from-point", "0.3,0", "--to-point", "0.7,0", "--speed", "2",
                         "--samples", "9", "--format", "table"});
  CHECK(table.code == 3);
  CHECK_THAT(table.out, Catch::Contains("unreachable"));
  CHECK_THAT(table.out, Catch::Contains("singular"));
}

TEST_CASE("arm leaves the rates empty where the arm is folded or stretched out", "[cli][arm]") {
  // Arm 3, 2 along +x from |p| = 1 (folded) to |p| = 5 (stretched), one sample per second.
  const Run r = run({"arm", "--arm", "3,2", "--from-point", "1,0", "--to-point", "5,0", "--speed", "1", "--samples",
                     "5", "--unit", "mm"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("the arm is folded at t = 0 s, tip (1, 0) mm"));
  CHECK_THAT(r.err, Catch::Contains("the arm is stretched out at t = 4 s, tip (5, 0) mm"));
  const Table t = parseCsv(r.out);
  REQUIRE(t.rows.size() == 5);
  for (const std::size_t row : {std::size_t{0}, std::size_t{4}}) {
    CHECK(t.value(row, "elbow_x_mm") == 3.0);
    CHECK(t.rows[row][t.column("upper_omega_rad_s")].empty());
    CHECK(t.rows[row][t.column("forearm_alpha_rad_s2")].empty());
  }
  CHECK_FALSE(t.rows[2][t.column("upper_omega_rad_s")].empty());
  // --step-time lists the grid from 0; here 0.05 s over the seed's 0.2121 s: 5 rows.
  const Run step = run({"arm", "--example", "seed-arm", "--step-time", "0.05"});
  REQUIRE(step.code == 0);
  const Table s = parseCsv(step.out);
  REQUIRE(s.rows.size() == 5);
  CHECK(s.rows[3][0] == "0.15");
}

TEST_CASE("arm -o writes the same CSV to a file", "[cli][arm]") {
  const auto file = std::filesystem::temp_directory_path() / "linkwright_arm_test.csv";
  std::filesystem::remove(file);
  const Run toFile = run({"arm", "--example", "seed-arm", "-o", file.string()});
  REQUIRE(toFile.code == 0);
  CHECK(toFile.out.empty());
  std::ifstream in(file, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == run({"arm", "--example", "seed-arm"}).out);
  std::filesystem::remove(file);
}

TEST_CASE("arm and centres: bad options exit 2 naming the option", "[cli][arm][centres][errors]") {
  using Args = std::vector<std::string>;
  auto [args, expected] = GENERATE(table<Args, std::string>({
      {Args{"arm"}, "arm needs --arm UPPER,FOREARM, or --example seed-arm"},
      {Args{"arm", "--arm", "0.3,0.2"}, "arm needs --from-point X,Y"},
      {Args{"arm", "--arm", "-0.3,0.2", "--from-point", "0.3,0", "--to-point", "0,0.3", "--speed", "2"},
       "--arm: upper length must be positive and finite (got -0.3)"},
      {Args{"arm", "--arm", "0.3,nan"}, "--arm: forearm length must be positive and finite (got undefined)"},
      {Args{"arm", "--arm", "0.3"}, "--arm expects UPPER,FOREARM (got '0.3')"},
      {Args{"arm", "--example", "seed-arm", "--speed", "nan"}, "--speed must be positive and finite (got undefined)"},
      {Args{"arm", "--example", "seed-arm", "--speed", "-2"}, "--speed must be positive and finite (got -2)"},
      {Args{"arm", "--example", "seed-arm", "--speed", "1e-300"},
       "--speed is too slow: the path of 0.424264 m would take 4.24264e+299 s, beyond 1e+06 s (the speed must be "
       "at least 4.24264e-07 m/s)"},
      {Args{"arm", "--example", "seed-arm", "--from-point", "1,inf"}, "--from-point: y must be finite (got undefined)"},
      {Args{"arm", "--example", "seed-arm", "--to-point", "0.3,0"},
       "--to-point must differ from --from-point (both are (0.3, 0))"},
      {Args{"arm", "--example", "seed-arm", "--frobnicate", "1"}, "unknown option '--frobnicate' for 'arm'"},
      {Args{"arm", "--example", "seed-arm", "--branch", "open"}, "unknown option '--branch' for 'arm'"},
      {Args{"arm", "--example", "seed-arm", "--elbow", "left"}, "--elbow must be 'up' or 'down' (got 'left')"},
      {Args{"arm", "--example", "seed-arm", "--samples", "1"}, "--samples must be at least 2 for arm (got 1)"},
      {Args{"arm", "--example", "seed-arm", "--step-time", "0"}, "--step-time must be positive and finite (got 0)"},
      {Args{"arm", "--example", "seed-arm", "--step-time", "0.1", "--samples", "3"},
       "--step-time and --samples cannot be used together"},
      {Args{"arm", "--example", "robot"}, "--example: no arm example named 'robot' (arm has one: seed-arm)"},
      {Args{"arm", "--example", "seed-arm", "--unit", "mm"}, "--unit: the seed-arm example is in metres"},
      {Args{"centres", "--example", "thesis-crank-rocker"}, "centres needs --at DEG"},
      {Args{"centres", "--at", "10"},
       "centres needs FILE.json, --fourbar FRAME,CRANK,COUPLER,ROCKER or --example NAME"},
      {Args{"centres", "--example", "thesis-crank-rocker", "--at", "nan"}, "--at must be finite (got nan)"},
      {Args{"centres", "--example", "thesis-crank-rocker", "--at", "10,x"}, "--at: 'x' is not a number"},
      {Args{"centres", "--fourbar", "60,25,-70,45", "--at", "10"},
       "--fourbar: coupler length must be positive and finite (got -70)"},
  }));
  CAPTURE(args);
  const Run r = run(args);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(expected));
}

// ---- centres: instant centres and mechanical advantage ------------------------------------

namespace {
// The number after `label` in the text, e.g. "ω4/ω2 = " → 0.590772611.
double numberAfter(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  REQUIRE(at != std::string::npos);
  return std::stod(text.substr(at + label.size()));
}
}  // namespace

TEST_CASE("centres prints the six centres and a velocity ratio equal to the solver's", "[cli][centres]") {
  const Run r = run({"centres", "--example", "thesis-crank-rocker", "--at", "90"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  const auto m = kinematics::makeFourBar({60, 25, 70, 45}, kinematics::Branch::Open);
  REQUIRE(m.ok());
  const auto pose = kinematics::solvePose(*m, {kinematics::degToRad(90), 1.0, 0.0});
  REQUIRE(pose.ok());
  const double w4 = pose->linkOmega[kinematics::fourbar::kRocker.index];
  // Printed to 9 significant digits.
  CHECK(numberAfter(r.out, "ω4/ω2 = ") == Approx(w4).epsilon(1e-8));
  CHECK(numberAfter(r.out, "T4/T2 = ω2/ω4 = ") == Approx(1.0 / w4).epsilon(1e-8));
  CHECK_THAT(r.out, Catch::Contains("I12  (0, 0) mm"));
  CHECK_THAT(r.out, Catch::Contains("I23  (0, 25) mm"));  // B straight above O2
  // I24 is where the coupler line meets the frame line (y = 0).
  CHECK_THAT(r.out, Catch::Contains("I24  (-86.6177525, 0) mm"));
  for (const char* name : {"I13", "I14", "I34"}) CHECK_THAT(r.out, Catch::Contains(name));
}

TEST_CASE("centres of a shaper: fifteen centres, the ram's v/ω2 equal to the solver's", "[cli][centres]") {
  const Run r = run({"centres", "--example", "shaper", "--at", "30"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("bodies 1 frame, 2 crank, 3 block B, 4 rocker, 5 link, 6 slider R"));
  CHECK_THAT(r.out, Catch::Contains("I16  at infinity, direction 90°"));  // the ram slides along x
  CHECK_THAT(r.out, Catch::Contains("slide at B: block B and rocker have no relative rotation"));
  CHECK_THAT(r.out, Catch::Contains("I13  (-252.099462, -145.549692) mm"));
  CHECK_THAT(r.out, Catch::Contains("on I12–I23 and I14–I34"));  // the lines that locate it
  CHECK(r.out.find("not located") == std::string::npos);
  const auto example = kinematics::findExample("shaper");
  const auto pose = kinematics::solvePose(example->mechanism, {kinematics::degToRad(30), 1.0, 0.0});
  REQUIRE(pose.ok());
  CHECK(numberAfter(r.out, "v/ω2 = ") == Approx(pose->velocity[kinematics::shaper::kRam.index].x()).epsilon(1e-8));
  // A two-link arm has two freedoms: one centre stays unresolved, and there is no crank.
  const Run arm = run({"centres", "--example", "seed-arm", "--at", "0.1"});
  REQUIRE(arm.code == 0);
  CHECK_THAT(arm.out, Catch::Contains("not located"));
  CHECK_THAT(arm.out, Catch::Contains("ratios: none"));
}

TEST_CASE("centres: points at infinity, toggles and angles that do not assemble", "[cli][centres]") {
  // Parallelogram: coupler translating (I13 at infinity along the crank), ratio exactly 1.
  const Run parallel = run({"centres", "--fourbar", "60,25,60,25", "--at", "30"});
  REQUIRE(parallel.code == 0);
  CHECK_THAT(parallel.out, Catch::Contains("I13  at infinity, direction 30°"));
  CHECK_THAT(parallel.out, Catch::Contains("I24  at infinity, direction 0°"));
  CHECK_THAT(parallel.out, Catch::Contains("ω4/ω2 = 1\n"));
  // The LS3 engine at top dead centre: the slider is at rest, F/T2 infinite; I14 is the
  // slider's point at infinity normal to the guide.
  const Run ls3 = run({"centres", "--example", "ls3-engine", "--at", "0", "--at", "45"});
  REQUIRE(ls3.code == 0);
  CHECK_THAT(ls3.out, Catch::Contains("I14  at infinity, direction 90°"));
  CHECK_THAT(ls3.out, Catch::Contains("F/T2 = ω2/v = infinite"));
  CHECK_THAT(ls3.out, Catch::Contains("dead centre"));
  CHECK_THAT(ls3.out, Catch::Contains("v/ω2 = -39.5133918 mm/rad"));  // analyze: C_vx = -39.513391788743 mm/s at ω 1
  // A triple-rocker cannot reach 120°: that angle is reported, the others still printed, exit 3.
  const Run partial = run({"centres", "--fourbar", "40,30,20,25", "--at", "0,120"});
  CHECK(partial.code == 3);
  CHECK_THAT(partial.err, Catch::Contains("crank angle 120°: C cannot be assembled"));
  CHECK_THAT(partial.out, Catch::Contains("crank angle 0°"));
  CHECK(run({"--help"}).out.find("centres    instant centres") != std::string::npos);
  CHECK(run({"--help", "arm"}).out.find("--elbow up|down") != std::string::npos);
}

TEST_CASE("centres accepts a linkage at the end of the domain as analyze, polygon, dxf and report do",
          "[cli][centres][domain]") {
  // Its solved joint C is at x = 2e9: centres refused it ("C.x must be within ±1e9"), as if typed.
  const std::vector<std::string> linkage{"--fourbar", "1e9,1e9,1e9,1e9", "--at", "1"};
  const auto with = [&linkage](std::vector<std::string> args) {
    args.insert(args.begin() + 1, linkage.begin(), linkage.end());
    return args;
  };
  const Run centres = run(with({"centres"}));
  INFO(centres.err);
  CHECK(centres.code == 0);
  CHECK(centres.err.empty());
  CHECK_THAT(centres.out, Catch::Contains("I13") && Catch::Contains("ω4/ω2 = "));
  CHECK(run(with({"polygon"})).code == 0);
  const Run analyze = run({"analyze", "--fourbar", "1e9,1e9,1e9,1e9", "--from", "1", "--to", "1"});
  CHECK(analyze.code == 0);
  CHECK_THAT(analyze.out, Catch::Contains(",1999847695.1563911,"));  // C_x: beyond ±1e9, and accepted
}

TEST_CASE("an --at out of its domain is bad input for every command, and a drawing's sizes are lengths",
          "[cli][errors]") {
  // --at 1e300 exited 3 (cannot be assembled) for centres, dxf and report, 2 for polygon.
  for (const char* command : {"centres", "dxf", "report", "polygon"}) {
    CAPTURE(command);
    std::vector<std::string> args{command, "--example", "thesis-crank-rocker", "--at", "1e300"};
    if (std::string(command) == "dxf" || std::string(command) == "report") {
      args.push_back("-o");
      args.push_back((std::filesystem::temp_directory_path() / "linkwright-at-test.out").string());
    }
    const Run r = run(args);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--at must be finite and within ±1e6 degrees (got 1e+300)"));
  }
  // dxf --hole and --width took 1e300 and 1e-300: 300-digit coordinates in the file.
  for (const auto& [option, value] : {std::pair{"--hole", "1e300"}, {"--width", "1e-300"}}) {
    CAPTURE(option, value);
    const Run r = run({"dxf", "--example", "thesis-crank-rocker", option, value, "-o",
                       (std::filesystem::temp_directory_path() / "linkwright-hole-test.dxf").string()});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(std::string(option) + " ") && Catch::Contains("must be between 1e-06 and 1e9"));
  }
}
