// linkwright-cli tolerance: the JSON holds the core's numbers (the Monte-Carlo worst deviation,
// the first-order worst case and the sensitivities, for the same seed and grid), the band CSV
// holds every column's nominal, low and high with low ≤ nominal ≤ high, the seed repeats, and
// every refusal names the option, the value and the range.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "kinematics/design/examples.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/json.h"
#include "kinematics/model/units.h"
#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include "tests/support/catch.h"

#include <cmath>
#include <filesystem>
#include <random>

namespace {

namespace k = linkwright::kinematics;
using linkwright::test::csvColumn;
using linkwright::test::runCliCommand;
namespace fs = std::filesystem;

// The example's grid every 30°, as the CLI builds it from --step 30.
k::SweepSpec thesisGrid() {
  const k::Example e = k::findExample("thesis-crank-rocker").value();
  k::SweepSpec spec;
  spec.fromAngle = 0.0;
  spec.toAngle = 2.0 * k::kPi;
  spec.samples = 13;
  spec.omega = e.omega;
  return spec;
}

}  // namespace

TEST_CASE("tolerance --json reports the core's worst deviations, first-order worst cases and sensitivities",
          "[cli][tolerance]") {
  const auto run = runCliCommand({"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05", "--step",
                                  "30", "--mc-samples", "200", "--seed", "9", "--json"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  const k::Mechanism m = k::findExample("thesis-crank-rocker")->mechanism;
  const auto mc = k::toleranceMonteCarlo(m, thesisGrid(), {0.05, 200, 9}).value();
  const auto s = k::sweepSensitivities(m, thesisGrid()).value();
  const std::vector<double> tolerances(s.dimensions.size(), 0.05);
  const auto summary = k::sensitivitySummary(m, thesisGrid(), tolerances).value();
  CHECK(json["tolerance_mm"].get<double>() == 0.05);
  CHECK(json["samples_in_band"].get<std::size_t>() == 200);
  CHECK(json["input_column"].get<std::string>() == "crank_angle_deg");
  REQUIRE(json["columns"].size() == mc.bands.size());
  for (std::size_t c = 0; c < mc.bands.size(); ++c) {
    const auto& column = json["columns"][c];
    INFO(mc.bands[c].column.name);
    CHECK(column["name"].get<std::string>() == mc.bands[c].column.name);
    CHECK(column["worst_deviation"].get<double>() == mc.bands[c].worstDeviation);
    CHECK(column["first_order_worst_on_grid"].get<double>() == s.firstOrderWorst(c, tolerances));
    CHECK(column["first_order_worst"].get<double>() == summary.firstOrderWorst[c]);
    CHECK(column["first_order_worst_at"].get<double>() == summary.firstOrderWorstInput[c]);
    CHECK(column["first_order_worst"].get<double>() >= column["first_order_worst_on_grid"].get<double>());
    CHECK(column["largest_sensitivity_per_mm"]["coupler length"].get<double>() ==
          summary.largest[c][2]);  // frame, crank, coupler, …
    CHECK(summary.largest[c][2] >= s.largest(c, 2));
  }
}

TEST_CASE("tolerance --at lists every sensitivity at that input", "[cli][tolerance]") {
  const auto run = runCliCommand({"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.1", "--mc-samples",
                                  "10", "--at", "90", "--json"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  CHECK(json["at"].get<double>() == Approx(90.0));
  k::SweepSpec one = thesisGrid();
  one.fromAngle = one.toAngle = k::degToRad(90.0);
  one.samples = 1;
  const auto s = k::sweepSensitivities(k::findExample("thesis-crank-rocker")->mechanism, one).value();
  for (std::size_t c = 0; c < s.columns.size(); ++c)
    for (std::size_t d = 0; d < s.dimensions.size(); ++d)
      CHECK(json["columns"][c]["sensitivity_at_per_mm"][s.dimensions[d].name].get<double>() == s.derivative[c][d][0]);
}

TEST_CASE("tolerance -o writes the band, the nominal between low and high, and a seed repeats", "[cli][tolerance]") {
  std::random_device random;
  const fs::path dir = fs::temp_directory_path() / ("linkwright-tolerance-cli-" + std::to_string(random()));
  fs::create_directories(dir);
  const auto band = [&](const std::string& seed, const std::string& name) {
    const fs::path path = dir / name;
    const auto run = runCliCommand({"tolerance", "--example", "ls3-engine", "--tolerance", "0.1", "--step", "10",
                                    "--mc-samples", "100", "--seed", seed, "-o", path.string()});
    INFO(run.err);
    REQUIRE(run.code == 0);
    CHECK(run.out.find("C_x_mm") != std::string::npos);
    return k::io::readFileBounded(path.string(), 1 << 24, "the band").value();
  };
  const std::string a = band("5", "a.csv"), b = band("5", "b.csv"), c = band("6", "c.csv");
  CHECK(a == b);
  CHECK(a != c);
  const auto nominal = csvColumn(a, "C_x_mm"), low = csvColumn(a, "low_C_x_mm"), high = csvColumn(a, "high_C_x_mm");
  REQUIRE(nominal.size() == 37);
  for (std::size_t j = 0; j < nominal.size(); ++j) {
    CHECK(low[j] <= nominal[j]);
    CHECK(nominal[j] <= high[j]);
    CHECK(high[j] - low[j] > 0.0);
  }
  fs::remove_all(dir);
}

TEST_CASE("tolerance refuses a bad tolerance, sample count or seed, naming the option and the range",
          "[cli][tolerance]") {
  const auto err = [](std::vector<std::string> extra) {
    std::vector<std::string> args{"tolerance", "--example", "thesis-crank-rocker"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = runCliCommand(args);
    CHECK(run.code == 2);
    CHECK(run.out.empty());
    return run.err;
  };
  CHECK(err({"--tolerance", "-0.05"}) ==
        "linkwright-cli: --tolerance: tolerance must be finite, at least 0 and less than the shortest length (crank "
        "length, 25 mm) (got -0.05 mm)\n");
  CHECK(err({"--tolerance", "nan"}).find("(got undefined)") != std::string::npos);
  CHECK(err({"--tolerance", "0.1", "--mc-samples", "100001"}) ==
        "linkwright-cli: --mc-samples must be between 1 and 100000 (got 100001)\n");
  CHECK(err({"--tolerance", "0.1", "--mc-samples", "0"}) ==
        "linkwright-cli: --mc-samples must be between 1 and 100000 (got 0)\n");
  CHECK(err({"--tolerance", "0.1", "--seed", "-3"}).find("--seed must be a whole number from 0") != std::string::npos);
  CHECK(err({}).find("tolerance needs --tolerance T") != std::string::npos);
}

TEST_CASE("tolerance's text names every output column and the help describes the command", "[cli][tolerance]") {
  const auto run =
      runCliCommand({"tolerance", "--example", "watt-ii", "--tolerance", "0.05", "--step", "30", "--mc-samples", "20"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  for (const auto& c : k::toleranceColumns(k::findExample("watt-ii")->mechanism))
    CHECK(run.out.find(c.name) != std::string::npos);
  CHECK(run.out.find("20 in the band") != std::string::npos);
  CHECK(run.out.find("nan") == std::string::npos);
  const auto help = runCliCommand({"--help", "tolerance"});
  CHECK(help.code == 0);
  CHECK(help.out.find("--mc-samples N") != std::string::npos);
}

TEST_CASE("tolerance --tolerance-of gives dimensions a ± of their own, and names a dimension it does not know",
          "[cli][tolerance]") {
  const auto r = runCliCommand({"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05", "--step", "30",
                                "--tolerance-of", "crank length=0,coupler length=0.5", "--mc-samples", "50", "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto json = k::io::parseJson(r.out).value();
  CHECK(json["own_tolerances_mm"]["crank length"].get<double>() == 0.0);
  CHECK(json["own_tolerances_mm"]["coupler length"].get<double>() == 0.5);
  // The study is the core's with those tolerances.
  k::MonteCarloSpec spec{0.05, 50, k::kDefaultToleranceSeed};
  spec.perDimension = {{"crank length", 0.0}, {"coupler length", 0.5}};
  const auto mc = k::toleranceMonteCarlo(k::findExample("thesis-crank-rocker")->mechanism, thesisGrid(), spec).value();
  REQUIRE(json["columns"].size() == mc.bands.size());
  for (std::size_t c = 0; c < mc.bands.size(); ++c)
    CHECK(json["columns"][c]["worst_deviation"].get<double>() == mc.bands[c].worstDeviation);

  const auto unknown = runCliCommand(
      {"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05", "--tolerance-of", "crank=0.1"});
  CHECK(unknown.code == 2);
  CHECK_THAT(unknown.err, Catch::Contains("--tolerance-of: no dimension is named 'crank'"));
  const auto malformed = runCliCommand(
      {"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05", "--tolerance-of", "crank length"});
  CHECK(malformed.code == 2);
  CHECK_THAT(malformed.err,
             Catch::Contains("--tolerance-of: 'crank length' is not NAME=T (e.g. \"coupler length=0.02\")"));
}

TEST_CASE("tolerance states the band's Monte-Carlo error and the samples an accuracy needs, in text and JSON",
          "[cli][tolerance]") {
  const std::vector<std::string> study{"tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05",
                                       "--step",    "30",        "--mc-samples",        "199"};
  auto withJson = study;
  withJson.push_back("--json");
  const auto run = runCliCommand(withJson);
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  const auto& e = json["monte_carlo_error"];
  const k::MonteCarloError core = k::monteCarloError(199);
  CHECK(e["samples"].get<std::size_t>() == 199);
  CHECK(e["confidence"].get<double>() == 0.95);
  CHECK(e["outside_band_chance"].get<double>() == 2.0 / 200);  // 2/(n+1)
  CHECK(e["beyond_worst_chance"].get<double>() == 1.0 / 200);
  CHECK(e["outside_band_at_confidence"].get<double>() == core.outsideBandBound);
  CHECK(e["beyond_worst_at_confidence"].get<double>() == Approx(1.0 - std::pow(0.05, 1.0 / 199)));
  CHECK(e["samples_for_outside_band"]["0.01"].get<std::size_t>() == 473);
  CHECK(e["samples_for_outside_band"]["0.001"].get<std::size_t>() == k::toleranceSamplesFor(0.001));
  const auto text = runCliCommand(study);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("Monte-Carlo error, for the 199 samples in the band: one more linkage falls outside the band at "
                      "an input with chance 2/(n+1) = 0.01 (with 95 % confidence at most ") != std::string::npos);
  CHECK(text.out.find("deviates more than a column's worst with chance 1/(n+1) = 0.005") != std::string::npos);
  CHECK(text.out.find("at most 1 % outside with 95 % confidence takes 473 samples in the band") != std::string::npos);
}
