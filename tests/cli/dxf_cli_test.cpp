// Tests `linkwright-cli dxf` in-process: it writes the file the core's exportLinkDrawingDxf
// writes for the same pose, says which layers and sizes it used, and refuses bad sizes, bad
// angles and missing options with exit code 2 or 3, naming the option, and writes nothing.
// (dxf_readback.py reads the files back with ezdxf.)

#include "tests/cli/run_cli.h"

#include "kinematics/design/examples.h"
#include "kinematics/io/dxf_export.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace k = linkwright::kinematics;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("dxf writes the core's drawing of the pose asked for", "[cli][dxf]") {
  const fs::path dir = scratchDir("dxf-cli");
  const std::string file = (dir / "thesis.dxf").string();
  const auto run = runCliCommand(
      {"dxf", "--example", "thesis-crank-rocker", "--at", "30", "--hole", "2", "--width", "6", "-o", file});
  REQUIRE(run.code == 0);
  CHECK_THAT(run.out, Catch::Contains("crank angle 30°, holes 2 mm, plates 6 mm wide"));
  CHECK_THAT(run.out, Catch::Contains("layers: GROUND crank coupler rocker"));
  CHECK_THAT(run.out, Catch::Contains("$INSUNITS 4"));
  const k::Example e = *k::findExample("thesis-crank-rocker");
  const auto pose = k::solvePose(e.mechanism, {k::degToRad(30.0), 0.0, 0.0}, k::SolveRequest{false, false});
  REQUIRE(pose.ok());
  const std::string same = (dir / "core.dxf").string();
  REQUIRE_FALSE(k::io::exportLinkDrawingDxf(e.mechanism, *pose, {2.0, 6.0}, same).has_value());
  CHECK(contents(file) == contents(same));
  fs::remove_all(dir);
}

TEST_CASE("dxf says when the unit has no DXF code", "[cli][dxf]") {
  const fs::path dir = scratchDir("dxf-cli");
  const auto run =
      runCliCommand({"dxf", "--fourbar", "60,25,70,45", "--unit", "furlong", "-o", (dir / "f.dxf").string()});
  REQUIRE(run.code == 0);
  CHECK_THAT(run.out, Catch::Contains("$INSUNITS 0 (unitless: 'furlong' has no DXF unit code)"));
  fs::remove_all(dir);
}

TEST_CASE("dxf refuses bad sizes and angles, naming the option, and writes nothing", "[cli][dxf][errors]") {
  const fs::path dir = scratchDir("dxf-cli");
  const std::string file = (dir / "x.dxf").string();
  struct Case {
    std::vector<std::string> args;
    int code;
    const char* message;
  };
  const Case cases[] = {
      {{"--hole", "0"}, 2, "--hole must be positive and finite (got 0)"},
      {{"--hole", "nan"}, 2, "--hole must be positive and finite (got undefined)"},
      {{"--hole", "-3"}, 2, "--hole must be positive and finite (got -3)"},
      // The thesis crank is 25 mm between its pivot and its pin: the shortest spacing.
      {{"--hole", "25"}, 2, "--hole: hole diameter must be less than 25 mm"},
      {{"--hole", "4", "--width", "4"}, 2, "--width: plate width must be finite and more than the hole diameter 4 mm"},
      {{"--width", "inf"}, 2, "--width must be positive and finite (got undefined)"},
      {{"--at", "1,2"}, 2, "--at takes one value (got 2)"},
      {{"--at", "nan"}, 2, "--at must be finite"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"dxf", "--example", "thesis-crank-rocker", "-o", file};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto run = runCliCommand(args);
    INFO(run.err);
    CHECK(run.code == c.code);
    CHECK_THAT(run.err, Catch::Contains(c.message));
    CHECK_FALSE(fs::exists(file));
  }
  // A non-Grashof four-bar cannot be assembled with its crank at 180°.
  const auto locked = runCliCommand({"dxf", "--fourbar", "60,40,30,20", "--at", "180", "-o", file});
  CHECK(locked.code == 3);
  CHECK_THAT(locked.err, Catch::Contains("--at: --fourbar cannot be assembled at crank angle 180°"));
  CHECK_FALSE(fs::exists(file));
  const auto noOutput = runCliCommand({"dxf", "--example", "thesis-crank-rocker"});
  CHECK(noOutput.code == 2);
  CHECK_THAT(noOutput.err, Catch::Contains("dxf needs -o FILE.dxf"));
  const auto noLinkage = runCliCommand({"dxf", "-o", file});
  CHECK(noLinkage.code == 2);
  CHECK_THAT(noLinkage.err, Catch::Contains("dxf needs FILE.json, --fourbar"));
  fs::remove_all(dir);
}
