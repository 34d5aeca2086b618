// linkwright-cli atlas: the JSON holds the core's classification of every cell the filter keeps
// (and only those), the CSV one row a kept cell, --cell writes a document whose P traces the
// cell's curve, and every refusal names the option, the value and the range.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <filesystem>

namespace {

namespace k = linkwright::kinematics;
using linkwright::test::csvColumn;
using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace fs = std::filesystem;

// A small grid that holds Hoeken's linkage (cell 1: coupler 2.5, rocker 2.5, frame 2, along 2).
const std::vector<std::string> kGrid{"atlas",   "--coupler", "2.5",      "--rocker", "2.5",       "--frame", "2,6.5",
                                     "--along", "0.5,2",     "--across", "0,0.4",    "--samples", "180"};

k::AtlasAxes gridAxes() {
  k::AtlasAxes axes;
  axes.coupler = {2.5};
  axes.rocker = {2.5};
  axes.frame = {2.0, 6.5};
  axes.along = {0.5, 2.0};
  axes.across = {0.0, 0.4};
  axes.samples = 180;
  return axes;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("atlas --json lists every cell with the core's classification", "[cli][atlas]") {
  const auto run = runCliCommand(with(kGrid, {"--json"}));
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto json = k::io::parseJson(run.out).value();
  const auto cells = k::computeAtlasPage(gridAxes(), 0, 8).value();
  REQUIRE(json["cells"] == 8);
  REQUIRE(json["matching"] == 8);
  // What each feature is found to: the core's tolerances at these samples.
  const k::ClassifierTolerances t = k::classifierTolerances(180);
  CHECK(json["tolerances"]["cusp"]["speed_per_rad"] == t.cuspSpeed);
  CHECK(json["tolerances"]["cusp"]["point"] == t.cuspPoint);
  CHECK(json["tolerances"]["crunode"]["point"] == t.crunodePoint);
  CHECK(json["tolerances"]["symmetry"]["deviation"] == t.symmetry);
  CHECK(json["tolerances"]["straight"]["ends_u_rad"] == t.runEnd);
  CHECK(json["tolerances"]["circular"]["deviation"] == t.circular);
  REQUIRE(json["atlas"].size() == 8);
  for (std::size_t i = 0; i < 8; ++i) {
    const auto& j = json["atlas"][i];
    const k::AtlasCell& c = cells[i];
    CAPTURE(i);
    CHECK(j["cell"] == i);
    CHECK(j["frame"].get<double>() == c.key.lengths.frame);
    CHECK(j["along"].get<double>() == c.key.point.along);
    CHECK(j["class"] == std::string(k::toString(c.grashof.category)));
    CHECK(j["crank"] == std::string(k::toString(c.motion)));
    CHECK(j["cusps"].size() == c.features.cusps.size());
    CHECK(j["crunodes"].size() == c.features.crunodes.size());
    CHECK(j["symmetry"].is_null() == !c.features.symmetry);
    CHECK(j["straight"].is_null() == !c.features.straight);
    CHECK(j["circular"].is_null() == !c.features.circular);
    if (c.features.straight) CHECK(j["straight"]["length"].get<double>() == c.features.straight->length);
  }
  // Hoeken's cell is straight and symmetric.
  CHECK(!json["atlas"][2]["straight"].is_null());
  CHECK(!json["atlas"][2]["symmetry"].is_null());
}

TEST_CASE("atlas --filter keeps only the cells that have every feature named", "[cli][atlas]") {
  const fs::path dir = scratchDir("atlas-cli");
  const fs::path csv = dir / "atlas.csv";
  const auto run = runCliCommand(with(kGrid, {"--filter", "straight,symmetric", "-o", csv.string()}));
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto cells = k::computeAtlasPage(gridAxes(), 0, 8).value();
  const auto kept = k::filterCells(cells, k::AtlasFilter{.symmetric = true, .straight = true});
  REQUIRE(!kept.empty());
  const auto text = k::io::readFileBounded(csv.string(), 1 << 20, "the atlas").value();
  const std::vector<double> numbers = csvColumn(text, "cell");
  REQUIRE(numbers.size() == kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) CHECK(numbers[i] == static_cast<double>(kept[i]));
  const std::vector<double> lengths = csvColumn(text, "straight_length");
  for (std::size_t i = 0; i < kept.size(); ++i) CHECK(lengths[i] == cells[kept[i]].features.straight->length);
  CHECK(run.out.find(std::to_string(kept.size()) + " match") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("atlas --cell writes the cell's four-bar as a document whose P traces its curve", "[cli][atlas]") {
  const fs::path dir = scratchDir("atlas-cli");
  const fs::path file = dir / "hoeken.linkwright";
  const auto run = runCliCommand(with(kGrid, {"--cell", "2", "--crank", "10", "-o", file.string()}));
  INFO(run.err);
  REQUIRE(run.code == 0);
  const auto text = k::io::readFileBounded(file.string(), k::io::kMaxDocumentBytes, "a document").value();
  const k::Design design = k::io::readDocument(text).value();
  const k::AtlasCell cell = k::computeAtlasCell(k::atlasCellKey(gridAxes(), 2)).value();
  k::SweepSpec spec;
  spec.toAngle = 2.0 * k::kPi * 179.0 / 180.0;
  spec.samples = 180;
  spec.omega = 1.0;
  const auto s = k::sweep(design.mechanism, spec).value();
  const auto p = design.mechanism.findPoint("P");
  REQUIRE(p.has_value());
  for (std::size_t j = 0; j < 180; ++j) CHECK((s.position[p->index][j] - 10.0 * cell.curve.point[j]).norm() < 1e-9);
  fs::remove_all(dir);
}

TEST_CASE("atlas refuses bad options, naming the option, the value and the range", "[cli][atlas]") {
  const auto refused = [](const std::vector<std::string>& args) {
    const auto run = runCliCommand(args);
    CHECK(run.code == 2);
    CHECK(run.out.empty());
    return run.err;
  };
  CHECK(refused({"atlas", "--coupler", "2,-1"}) ==
        "linkwright-cli: --coupler ratios must be between 0.001 and 1000 crank lengths (got -1)\n");
  CHECK(refused({"atlas", "--frame", "2,x"}) ==
        "linkwright-cli: --frame: 'x' is not a number (expected numbers separated by commas)\n");
  CHECK(refused({"atlas", "--across", "1e9"}) ==
        "linkwright-cli: --across must be finite and within ±100 coupler lengths (got 1e+09)\n");
  CHECK(refused({"atlas", "--samples", "-5"}) == "linkwright-cli: --samples must be between 36 and 100000 (got -5)\n");
  CHECK(refused({"atlas", "--samples", "many"}) == "linkwright-cli: --samples: 'many' is not a whole number\n");
  CHECK(refused({"atlas", "--filter", "loops"}) ==
        "linkwright-cli: --filter takes cusp, crunode, symmetric, straight or circular, separated by commas (got "
        "'loops')\n");
  CHECK(refused({"atlas", "--branch", "up"}) == "linkwright-cli: --branch must be 'open' or 'crossed' (got 'up')\n");
  CHECK(refused({"atlas", "--cell", "720", "-o", "x.linkwright"}) ==
        "linkwright-cli: --cell must be between 0 and 719, the grid's cells (got 720)\n");
  CHECK(refused({"atlas", "--cell", "3"}) ==
        "linkwright-cli: --cell needs -o FILE.linkwright (where to write the cell's design)\n");
  CHECK(refused({"atlas", "--cell", "3", "--json", "-o", "x"}) ==
        "linkwright-cli: --json goes with the table, not with --cell\n");
  CHECK(refused({"atlas", "--crank", "2"}) ==
        "linkwright-cli: --crank sets the design --cell writes; give --cell I too\n");
  CHECK(refused({"atlas", "--cell", "0", "--crank", "0", "-o", "x"}) ==
        "linkwright-cli: --crank length must be positive and finite (got 0)\n");
  CHECK(refused({"atlas", "--fourbar", "1,2,3,4"}) ==
        "linkwright-cli: unknown option '--fourbar' for 'atlas' (see linkwright-cli --help atlas)\n");
  CHECK(refused({"atlas", "--json", "--json"}) == "linkwright-cli: --json is given more than once\n");
  {
    std::string many = "1";
    for (int i = 2; i <= 64; ++i) many += "," + std::to_string(i);
    CHECK(refused({"atlas", "--coupler", many, "--rocker", many, "--frame", many, "--along", many, "--across", many}) ==
          "linkwright-cli: --coupler × --rocker × --frame × --along × --across is 64 × 64 × 64 × 64 × 64 = "
          "1073741824 cells; atlas computes at most 100000 in one run: give fewer values\n");
    CHECK(refused({"atlas", "--coupler", many, "--rocker", many, "--frame",
                   "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,"
                   "19,20,21,22,23,24,25"}) ==
          "linkwright-cli: --coupler × --rocker × --frame × --along × --across is 64 × 64 × 25 × 5 × 3 = 1536000 "
          "cells; atlas computes at most 100000 in one run: give fewer values\n");
  }

  SECTION("a cell that never assembles is not written") {
    const fs::path dir = scratchDir("atlas-cli");
    const auto run = runCliCommand(with(kGrid, {"--cell", "4", "-o", (dir / "x.linkwright").string()}));
    CHECK(run.code == 3);
    CHECK(run.err == "linkwright-cli: --cell 4: this atlas cell's four-bar cannot be assembled at any crank angle\n");
    CHECK(!fs::exists(dir / "x.linkwright"));
    fs::remove_all(dir);
  }
  SECTION("--help atlas lists the options") {
    const auto run = runCliCommand({"atlas", "--help"});
    CHECK(run.code == 0);
    CHECK(run.out.find("--filter F,...") != std::string::npos);
  }
}
