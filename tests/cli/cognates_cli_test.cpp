// linkwright-cli cognates: the two documents are written, each a four-bar with its coupler
// point P, and analyze's P columns for them lie on the original's coupler curve; the table and
// the JSON say what the core found; every refusal exits with its code and writes nothing.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "kinematics/design/design.h"
#include "kinematics/explore/cognates.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/recognise.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <tuple>

namespace {

namespace k = linkwright::kinematics;
using linkwright::test::csvColumn;
using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace fs = std::filesystem;

k::Design readBack(const fs::path& path) {
  const auto text = k::io::readFileBounded(path.string(), k::io::kMaxDocumentBytes, "a Linkwright document");
  REQUIRE(text.ok());
  auto design = k::io::readDocument(*text);
  REQUIRE(design.ok());
  return *design;
}

// The distance from (x, y) to the thesis four-bar's coupler curve with P at (35, 20): the
// original solved at every crank angle of a fine grid, then refined by golden section on the
// exact solver around the nearest sample (both branches: the open one is the thesis's).
double distanceToThesisCurve(const Eigen::Vector2d& target) {
  const k::Design thesis =
      k::fourBarDesign(k::kThesisCrankRocker, k::Branch::Open, "mm", k::CouplerPointSpec{35.0, 20.0}).value();
  k::SolveRequest positions;
  positions.velocities = positions.accelerations = false;
  const auto at = [&](double angle) {
    return (k::solvePose(thesis.mechanism, k::DriverState{angle, 0.0, 0.0}, positions).value().position[4] - target)
        .norm();
  };
  const int n = 3600;
  int best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
    if (const double d = at(2.0 * k::kPi * i / n); d < nearest) {
      nearest = d;
      best = i;
    }
  double lo = 2.0 * k::kPi * (best - 1) / n, hi = 2.0 * k::kPi * (best + 1) / n;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 100; ++i) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (at(a) < at(b)) hi = b;
    else lo = a;
  }
  return std::min(nearest, at((lo + hi) / 2.0));
}

}  // namespace

TEST_CASE("cognates writes two four-bars whose P analyze finds on the original's coupler curve", "[cli][cognates]") {
  const fs::path dir = scratchDir("cognates-cli");
  const std::string prefix = (dir / "thesis").string();
  const auto r =
      runCliCommand({"cognates", "--example", "thesis-crank-rocker", "--coupler-point", "35,20", "-o", prefix});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("cognates of the coupler point P (z = 0.5 + 0.28571i: P = B + z (C − B)), built at the "
                   "original's crank angle 0°; third ground pivot O6 at (30, 17.1429) mm") != std::string::npos);
  CHECK(r.out.find("crank-rocker") != std::string::npos);
  CHECK(r.out.find("double-rocker") != std::string::npos);
  CHECK(r.out.find("25.21°") != std::string::npos);
  CHECK(r.out.find("Drive its crank at the original crank's ω (ratio 1, a constant speed)") != std::string::npos);
  CHECK(r.out.find("its crank must turn at the original coupler's ω3, which is not constant") != std::string::npos);
  for (const int i : {1, 2}) {
    CAPTURE(i);
    const fs::path file = dir / ("thesis-" + std::to_string(i) + ".linkwright");
    REQUIRE(fs::exists(file));
    const k::Design design = readBack(file);
    REQUIRE(k::asFourBar(design.mechanism).has_value());
    REQUIRE(design.mechanism.findPoint("P").has_value());
    // The written document analysed by the CLI: its P column on the original's curve.
    const auto table = runCliCommand({"analyze", file.string(), "--samples", "37"});
    REQUIRE(table.code == 0);
    const std::vector<double> x = csvColumn(table.out, "P_x_mm"), y = csvColumn(table.out, "P_y_mm");
    REQUIRE(x.size() == 37);
    double worst = 0.0;
    for (std::size_t j = 0; j < x.size(); ++j) worst = std::max(worst, distanceToThesisCurve({x[j], y[j]}));
    CHECK(worst <= 1e-9 * 70.0);
  }
  // Cognate 2 runs on the original's grid at its speed; cognate 1's grid is its crank's swing.
  const k::Design second = readBack(dir / "thesis-2.linkwright");
  CHECK(second.fromDeg == 0.0);
  CHECK(second.toDeg == 360.0);
  CHECK(second.omega == Approx(2.0 * k::kPi * 10.0 / 60.0));
  const k::Design first = readBack(dir / "thesis-1.linkwright");
  CHECK(first.toDeg - first.fromDeg < 180.0);
  fs::remove_all(dir);
}

TEST_CASE("cognates --json says what the core found, and --coupler-point NAME picks the point", "[cli][cognates]") {
  const fs::path dir = scratchDir("cognates-cli");
  const fs::path original = dir / "original.linkwright";
  {
    const k::Design d =
        k::fourBarDesign(k::kThesisCrankRocker, k::Branch::Open, "mm", k::CouplerPointSpec{35.0, 20.0}).value();
    REQUIRE_FALSE(k::io::writeFileSafely(original.string(), k::io::writeDocument(d)).has_value());
  }
  const std::string prefix = (dir / "c").string();
  const auto r = runCliCommand({"cognates", original.string(), "--coupler-point", "P", "--json", "-o", prefix});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto json = k::io::parseJson(r.out);
  REQUIRE(json.ok());
  const k::CognateSet set = k::cognates(readBack(original)).value();
  CHECK((*json)["coupler_point"] == "P");
  CHECK((*json)["z"][0].get<double>() == set.z.real());
  CHECK((*json)["z"][1].get<double>() == set.z.imag());
  const auto& linkages = (*json)["linkages"];
  REQUIRE(linkages.size() == 3);
  const std::array<const k::CognateFourBar*, 3> bars{&set.original, &set.cognates[0], &set.cognates[1]};
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    const auto& l = linkages[i];
    CHECK(l["class"] == std::string(k::toString(bars[i]->grashof.category)));
    CHECK(l["lengths"]["crank"].get<double>() == bars[i]->fourBar.lengths.crank);
    CHECK(l["worst_transmission_deg"].get<double>() == k::radToDeg(*bars[i]->worstTransmission));
    CHECK(l["crank_turns_with"] == std::string(k::toString(bars[i]->turnsWith[0])));
    CHECK(l["crank_speed_ratio_max"].get<double>() == *bars[i]->crankSpeedRatioMax);
  }
  CHECK(linkages[0]["file"].is_null());
  CHECK(linkages[2]["file"] == prefix + "-2.linkwright");
  CHECK(fs::exists(prefix + "-1.linkwright"));
  fs::remove_all(dir);
}

TEST_CASE("cognates refuses what has no cognates, and writes nothing", "[cli][cognates]") {
  const fs::path dir = scratchDir("cognates-cli");
  const std::string prefix = (dir / "out").string();
  const std::vector<std::tuple<std::vector<std::string>, int, std::string>> cases{
      {{"cognates", "--example", "thesis-crank-rocker"}, 2, "cognates needs -o PREFIX"},
      {{"cognates", "-o", prefix}, 2, "cognates needs FILE.json, --fourbar FRAME,CRANK,COUPLER,ROCKER or --example"},
      {{"cognates", "--example", "thesis-crank-rocker", "-o", prefix},
       2,
       "this four-bar has no point fixed on its coupler, and cognates are the linkages that trace such a point's "
       "curve: add a coupler point first (--coupler-point U,V adds P"},
      {{"cognates", "--example", "ls3-engine", "-o", prefix}, 2, "and this slider-crank is not one"},
      {{"cognates", "--example", "miranda-fourbar", "--coupler-point", "Q", "-o", prefix},
       2,
       "--coupler-point: couplerPoint must name a point fixed on the coupler (got \"Q\"; the points on it: P)"},
      {{"cognates", "--fourbar", "60,25,70,45", "--coupler-point", "70,0", "-o", prefix},
       2,
       "the coupler point P is at C, the coupler–rocker joint, where cognate 2 shrinks to a point"},
      {{"cognates", "--fourbar", "50,60,20,45", "--coupler-point", "10,10", "-o", prefix},
       3,
       "the four-bar cannot be assembled at the start of its grid, where its cognates are constructed: C cannot be "
       "assembled at crank angle 0°"},
      {{"cognates", "--example", "miranda-fourbar", "--branch", "open", "-o", prefix},
       2,
       "unknown option '--branch' for 'cognates'"},
      {{"cognates", "--example", "miranda-fourbar", "-o", (dir / "missing" / "out").string()}, 1, "cannot write"},
  };
  for (const auto& [args, code, message] : cases) {
    CAPTURE(args);
    const auto r = runCliCommand(args);
    CHECK(r.code == code);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(r.out.empty());
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}
