// linkwright-cli optimise: the written document, analysed by `analyze` and by the core, gives
// the objective the command printed, better than the start's; the JSON says what the core
// found; the text names the changed dimensions; a seed repeats the document; every refusal
// names the option, exits with its code and writes nothing.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/tune/optimise_linkage.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace {

namespace k = linkwright::kinematics;
using linkwright::test::csvColumn;
using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  const auto text = k::io::readFileBounded(path.string(), k::io::kMaxDocumentBytes, "a Linkwright document");
  REQUIRE(text.ok());
  return *text;
}

double peakOfColumn(const std::string& csv, const std::string& name) {
  double peak = 0.0;
  for (const double v : csvColumn(csv, name)) peak = std::max(peak, std::abs(v));
  return peak;
}

// The distance of `target` from the polyline through `path`'s points (its nearest segment).
double distanceFromPolyline(const Eigen::Vector2d& target, const std::vector<Eigen::Vector2d>& path) {
  double best = (target - path.front()).norm();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], ab = path[i] - a;
    const double squared = ab.squaredNorm();
    const double t = squared > 0.0 ? std::clamp((target - a).dot(ab) / squared, 0.0, 1.0) : 0.0;
    best = std::min(best, (target - (a + t * ab)).norm());
  }
  return best;
}

// The largest |value| of the quantity `name` in `extremes`' table (its minimum and maximum,
// refined between the samples): what optimise's exact peak must equal.
double refinedPeak(const std::string& table, const std::string& name) {
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    std::string quantity;
    double minimum = 0.0, minimumAt = 0.0, maximum = 0.0;
    if (row >> quantity >> minimum >> minimumAt >> maximum && quantity == name)
      return std::max(std::abs(minimum), std::abs(maximum));
  }
  FAIL("no row " << name << " in\n" << table);
  return 0.0;
}

}  // namespace

TEST_CASE("optimise writes a design whose analysed peak alpha is the one printed, below the start's", "[cli]") {
  const fs::path dir = scratchDir("optimise-cli");
  const std::string file = (dir / "better.linkwright").string();
  const auto run = runCliCommand({"optimise", "--example", "thesis-crank-rocker", "--objective", "peak-alpha:rocker",
                                  "--evaluations", "200", "--starts", "2", "--json", "-o", file});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  const double before = json["before"].get<double>(), after = json["after"].get<double>();
  CHECK(json["unit"].get<std::string>() == "rad/s²");
  CHECK(json["improved"].get<bool>());
  CHECK(json["grashof_after"].get<std::string>() == "crank-rocker");
  CHECK(json["pivots_kept"].get<bool>());
  CHECK(after < 0.9 * before);

  // The peaks are exact: extremes of the start and of the written document give them, to its
  // 9 printed digits; analyze's samples every 0.5° come only within 1e-4 (7.4e-5 low).
  const auto start = runCliCommand({"analyze", "--example", "thesis-crank-rocker", "--step", "0.5"});
  REQUIRE(start.code == 0);
  CHECK(peakOfColumn(start.out, "rocker_alpha_rad_s2") == Approx(before).epsilon(1e-4));
  const auto startPeaks = runCliCommand({"extremes", "--example", "thesis-crank-rocker"});
  REQUIRE(startPeaks.code == 0);
  CHECK(refinedPeak(startPeaks.out, "rocker_alpha_rad_s2") == Approx(before).epsilon(1e-8));
  const auto analysed = runCliCommand({"extremes", file});
  INFO(analysed.err);
  REQUIRE(analysed.code == 0);
  CHECK(refinedPeak(analysed.out, "rocker_alpha_rad_s2") == Approx(after).epsilon(1e-8));

  // The document is the core's result for the same request, to the last bit.
  k::OptimiseRequest request;
  request.objective = {k::ObjectiveKind::PeakAlpha, "rocker"};
  request.options.evaluations = 200;
  request.options.starts = 2;
  const auto core = k::optimiseLinkage(*k::designForExample("thesis-crank-rocker"), request);
  REQUIRE(core.ok());
  CHECK(readText(file) == k::io::writeDocument(core->design));
  const auto& dims = json["dimensions"];
  REQUIRE(dims.size() == core->dimensions.size());
  CHECK(dims[1]["name"].get<std::string>() == "crank length");
  CHECK(dims[1]["after"].get<double>() == core->values[1]);
  fs::remove_all(dir);
}

TEST_CASE("optimise path: the written document's P path, analysed, is the printed distance from the targets", "[cli]") {
  const fs::path dir = scratchDir("optimise-cli");
  // Targets on the Miranda four-bar's curve of a coupler point lifted 30 mm off the coupler.
  const auto lifted =
      k::fourBarDesign({250.0, 100.0, 225.0, 150.0}, k::Branch::Open, "mm", k::CouplerPointSpec{112.5, 30.0});
  REQUIRE(lifted.ok());
  std::string csv = "x_mm,y_mm\n";
  std::vector<Eigen::Vector2d> targets;
  for (const double deg : {0.0, 72.0, 144.0, 216.0, 288.0}) {
    const auto pose = k::solvePose(lifted->mechanism, {k::degToRad(deg), 0.0, 0.0});
    REQUIRE(pose.ok());
    targets.push_back(pose->position[lifted->mechanism.findPoint("P")->index]);
    csv += k::formatNumber(targets.back().x()) + "," + k::formatNumber(targets.back().y()) + "\n";
  }
  const std::string table = (dir / "targets.csv").string(), file = (dir / "path.linkwright").string();
  REQUIRE_FALSE(k::io::writeFileSafely(table, csv));
  const auto run = runCliCommand({"optimise", "--example", "miranda-fourbar", "--objective", "path:" + table,
                                  "--evaluations", "300", "--json", "-o", file});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  CHECK(json["unit"].get<std::string>() == "mm");
  CHECK(json["after"].get<double>() < 0.5 * json["before"].get<double>());

  // The path analyze gives for the written document every 0.01°, the worst target's distance
  // from it: the printed distance is the path's (its chords there are within 1e-6 mm of it).
  const auto analysed = runCliCommand({"analyze", file, "--step", "0.01"});
  REQUIRE(analysed.code == 0);
  const std::vector<double> x = csvColumn(analysed.out, "P_x_mm"), y = csvColumn(analysed.out, "P_y_mm");
  std::vector<Eigen::Vector2d> path;
  for (std::size_t j = 0; j < x.size(); ++j) path.emplace_back(x[j], y[j]);
  double worst = 0.0;
  for (const Eigen::Vector2d& t : targets) worst = std::max(worst, distanceFromPolyline(t, path));
  CHECK(worst == Approx(json["after"].get<double>()).margin(1e-5));
  fs::remove_all(dir);
}

TEST_CASE("optimise prints the objective before and after and the dimensions it changed", "[cli]") {
  const fs::path dir = scratchDir("optimise-cli");
  const std::string file = (dir / "wide.linkwright").string();
  const auto run = runCliCommand({"optimise", "--example", "thesis-crank-rocker", "--objective", "transmission",
                                  "--fix-pivots", "O2", "--length-range", "30", "--evaluations", "150", "-o", file});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(run.out.rfind("worst transmission angle of the example thesis-crank-rocker: ", 0) == 0);
  CHECK(run.out.find("kept: Grashof class crank-rocker, branch, assembly over the whole grid") != std::string::npos);
  CHECK(run.out.find("  frame length: 60 → ") != std::string::npos);
  CHECK(run.out.find("[42, 78]") != std::string::npos);  // the frame's ±30 %
  CHECK(run.out.find("  O2 x: 0 (fixed)") != std::string::npos);
  CHECK(fs::exists(file));
  fs::remove_all(dir);
}

TEST_CASE("optimise refuses bad requests naming the option and writes nothing", "[cli]") {
  const fs::path dir = scratchDir("optimise-cli");
  const std::string file = (dir / "never.linkwright").string();
  const auto refused = [&](std::vector<std::string> args, const std::string& message, int code = 2) {
    args.insert(args.begin(), "optimise");
    args.insert(args.end(), {"-o", file});
    const auto run = runCliCommand(args);
    CAPTURE(args);
    CHECK(run.code == code);
    CHECK(run.err == "linkwright-cli: " + message + "\n");
    CHECK_FALSE(fs::exists(file));
  };
  refused({"--example", "thesis-crank-rocker", "--objective", "peak-alpha:boom"},
          "--objective: the linkage has no link named 'boom' (its links: crank, coupler, rocker)");
  refused({"--example", "thesis-crank-rocker", "--objective", "rms-torque"},
          "--objective: the RMS driving torque needs the links' masses, and the design has none (give them in the "
          "Forces tab or the document's dynamics)");
  refused({"--example", "thesis-crank-rocker", "--objective", "fastest"},
          "--objective must be peak-alpha:LINK, transmission, path:TARGETS.csv or rms-torque (got 'fastest')");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--fix-pivots", "O2,C"},
          "--fix-pivots: 'C' is not a ground pivot of the linkage");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--length-range", "120"},
          "--length-range must be above 0 and at most 95, a percentage of each length (got 120)");
  // So small that it is 0 as a fraction: refused as typed, not as the core's "lengthRange".
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--length-range", "5e-324"},
          "--length-range must be above 0 and at most 95, a percentage of each length (got 5e-324)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--evaluations", "3"},
          "--evaluations must be between 10 and 1000000 (got 3)");
  const std::string targets = (dir / "targets.csv").string();
  REQUIRE_FALSE(k::io::writeFileSafely(targets, "10,20\n30,40\n"));
  refused({"--example", "thesis-crank-rocker", "--objective", "path:" + targets, "--path-measure", "mean"},
          "--path-measure must be worst or rms (got 'mean')");
  // Counts beyond an int are refused as typed, not wrapped (4294968796 ran 1500 designs).
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--evaluations", "4294968796"},
          "--evaluations must be between 10 and 1000000 (got 4294968796)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--evaluations", "1000001"},
          "--evaluations must be between 10 and 1000000 (got 1000001)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--evaluations", "99999999999999999999"},
          "--evaluations must be between 10 and 1000000 (got 99999999999999999999)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--starts", "4294967298"},
          "--starts must be between 1 and 1000 (got 4294967298)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--starts", "-4294967295"},
          "--starts must be between 1 and 1000 (got -4294967295)");
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--starts", "2.5"},
          "--starts: '2.5' is not a whole number");
  // The options of a path objective with another objective would be ignored.
  refused({"--example", "thesis-crank-rocker", "--objective", "transmission", "--point", "nosuch"},
          "--point goes with --objective path:TARGETS.csv (got --objective transmission)");
  refused({"--example", "thesis-crank-rocker", "--objective", "peak-alpha:coupler", "--path-measure", "rms"},
          "--path-measure goes with --objective path:TARGETS.csv (got --objective peak-alpha:coupler)");
  refused({"--example", "thesis-crank-rocker", "--objective", "path:" + (dir / "none.csv").string()},
          "--objective: " + (dir / "none.csv").string() + ": cannot be opened for reading: No such file or directory");

  const std::string empty = (dir / "empty.csv").string();
  REQUIRE_FALSE(k::io::writeFileSafely(empty, "x_mm,y_mm\n"));
  const auto run =
      runCliCommand({"optimise", "--example", "thesis-crank-rocker", "--objective", "path:" + empty, "-o", file});
  CHECK(run.code == 2);
  CHECK(run.err.find("--objective: ") == 16);
  CHECK_FALSE(fs::exists(file));
  fs::remove_all(dir);
}

TEST_CASE("optimise refuses a design whose grid it cannot sweep for every candidate", "[cli]") {
  // 10⁷ samples: every candidate swept whole took 3.6 GB; the refusal names the grid's size.
  const auto dir = linkwright::test::scratchDir("optimise-grid");
  k::Design design = *k::designForExample("thesis-crank-rocker");
  design.samples = 10'000'000;
  const std::string path = (dir / "fine.linkwright").string();
  REQUIRE_FALSE(k::io::writeFileSafely(path, k::io::writeDocument(design)));
  const auto r =
      runCliCommand({"optimise", path, "--objective", "transmission", "-o", (dir / "out.linkwright").string()});
  CHECK(r.code == 2);
  CHECK(r.err.find("optimise sweeps every candidate over the design's grid, which may hold at most 100000 samples "
                   "(got 10000000)") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out.linkwright"));
  design.samples = 721;
  REQUIRE_FALSE(k::io::writeFileSafely(path, k::io::writeDocument(design)));
  CHECK(runCliCommand({"optimise", path, "--objective", "transmission", "--evaluations", "20", "-o",
                       (dir / "out.linkwright").string()})
            .code == 0);
  std::filesystem::remove_all(dir);
}
