// `polygon` and `inversions` run in-process: the read-out carries the core's numbers (the JSON
// polygon's equation ends are the solver's velocities of the same pose), the text names the
// equations and classes a student looks for, and bad values exit 2 naming the option.

#include "tests/cli/run_cli.h"

#include "kinematics/design/examples.h"
#include "kinematics/io/json.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using linkwright::test::runCliCommand;
namespace k = linkwright::kinematics;

namespace {
Eigen::Vector2d vec(const k::io::JsonValue& j) { return {j[0].get<double>(), j[1].get<double>()}; }
}  // namespace

TEST_CASE("polygon prints the thesis linkage's equations and closes on the solver", "[cli][polygon]") {
  const auto r = runCliCommand({"polygon", "--example", "thesis-crank-rocker", "--at", "30"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::Contains("V_B = ω × O2B"));
  CHECK_THAT(r.out, Catch::Contains("V_C = V_B + V_CB"));
  CHECK_THAT(r.out, Catch::Contains("A_C = A_B + A^n_CB + A^t_CB = A^n_C + A^t_C"));
  CHECK_THAT(r.out, Catch::Contains("velocity polygon (mm/s)"));
  CHECK_THAT(r.out, Catch::Contains("acceleration polygon (mm/s²)"));
}

TEST_CASE("polygon --json: each equation ends on the solver's value of its point", "[cli][polygon]") {
  const k::Example ex = *k::findExample("shaper");
  const auto r = runCliCommand({"polygon", "--example", "shaper", "--at", "60,200", "--alpha", "4", "--json"});
  REQUIRE(r.code == 0);
  const auto json = k::io::parseJson(r.out);
  REQUIRE(json);
  REQUIRE(json->size() == 2);
  for (const auto& at : *json) {
    const double deg = at["crank_angle_deg"].get<double>();
    CAPTURE(deg);
    const auto pose = k::solvePose(ex.mechanism, {k::degToRad(deg), ex.omega, 4.0});
    REQUIRE(pose);
    for (const char* kind : {"velocity", "acceleration"}) {
      const auto& p = at[kind];
      double size = (vec(p["box"]["upper"]) - vec(p["box"]["lower"])).norm();
      bool coriolis = false;
      for (const auto& v : p["vectors"]) coriolis = coriolis || v["label"].get<std::string>() == "A^c_B";
      CHECK(coriolis == (std::string(kind) == "acceleration"));
      for (const auto& e : p["equations"])
        for (const auto& end : e["ends"]) CHECK((vec(end) - vec(e["solver"])).norm() <= 1e-9 * size);
      // The ram's equation ends on the solver's ram velocity (acceleration) at this pose.
      const auto& ram = p["equations"].back();
      const Eigen::Vector2d solver = std::string(kind) == "velocity" ? pose->velocity[4] : pose->acceleration[4];
      CHECK((vec(ram["solver"]) - solver).norm() <= 1e-12 * size);
    }
  }
}

TEST_CASE("polygon at a toggle exits 3 and says why", "[cli][polygon]") {
  const auto r = runCliCommand({"polygon", "--fourbar", "3,2,3,4", "--at", "0"});
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("toggle"));
}

TEST_CASE("inversions of the thesis crank-rocker follow Grashof's table", "[cli][inversions]") {
  const auto r = runCliCommand({"inversions", "--example", "thesis-crank-rocker"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("ground the frame: crank-rocker; drive the crank (turns fully)"));
  CHECK_THAT(r.out, Catch::Contains("ground the crank: double-crank (drag link)"));
  CHECK_THAT(r.out, Catch::Contains("ground the coupler: crank-rocker"));
  CHECK_THAT(r.out, Catch::Contains("ground the rocker: double-rocker (Grashof)"));
  const auto j = runCliCommand({"inversions", "--fourbar", "8,2,5,4", "--json"});
  REQUIRE(j.code == 0);
  const auto json = k::io::parseJson(j.out);
  REQUIRE(json);
  for (const auto& inv : (*json)["inversions"]) CHECK(inv["class"].get<std::string>() == "triple-rocker");
}

TEST_CASE("inversions of the LS3 engine name the four slider-crank inversions", "[cli][inversions]") {
  const auto r = runCliCommand({"inversions", "--example", "ls3-engine"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("ground the frame (guide): slider-crank"));
  CHECK_THAT(r.out, Catch::Contains("ground the crank: Whitworth quick return (rotating guide)"));
  CHECK_THAT(r.out, Catch::Contains("ground the rod: oscillating cylinder"));
  CHECK_THAT(r.out, Catch::Contains("ground the slider: fixed piston (pendulum pump); drive the rod (rocks)"));
}

TEST_CASE("polygon and inversions: bad values exit 2 naming the option and range", "[cli][polygon][errors]") {
  using Args = std::vector<std::string>;
  const auto [args, expected] = GENERATE(table<Args, std::string>({
      {Args{"polygon", "--example", "thesis-crank-rocker"}, "polygon needs --at DEG"},
      {Args{"polygon", "--at", "10"}, "polygon needs FILE.json, --fourbar FRAME,CRANK,COUPLER,ROCKER"},
      {Args{"polygon", "--example", "thesis-crank-rocker", "--at", "2e6"},
       "--at must be finite and within ±1e6 degrees (got 2e+06)"},
      {Args{"polygon", "--example", "thesis-crank-rocker", "--at", "10", "--omega", "2e6"},
       "--omega must be finite and within ±1e6 rad/s (got 2e+06)"},
      {Args{"polygon", "--example", "thesis-crank-rocker", "--at", "10", "--alpha", "nan"},
       "--alpha must be finite and within"},
      {Args{"polygon", "--example", "excavator-boom", "--at", "10"}, "polygon needs a crank-driven linkage"},
      {Args{"polygon", "--example", "thesis-crank-rocker", "--at", "10", "--step", "5"},
       "unknown option '--step' for 'polygon'"},
      {Args{"inversions", "--example", "shaper"}, "inversions needs a four-bar or a slider-crank"},
      // It said "needs a four-bar or a slider-crank (the example piston-driven is a slider-crank)".
      {Args{"inversions", "--example", "piston-driven"},
       "inversions needs a four-bar or a slider-crank driven by its crank; the example piston-driven is a "
       "slider-crank driven by its C path position, a length, so it has no crank to build the inversions from"},
      {Args{"inversions", "--example", "excavator-boom"},
       "the example excavator-boom is a cylinder rocker driven by its actuator A–C length, a length"},
      {Args{"inversions", "--fourbar", "60,0,70,45"}, "--fourbar: crank length must be positive and finite (got 0)"},
  }));
  CAPTURE(args);
  const auto r = runCliCommand(args);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(expected));
}
