// The sweep grid a front end asks for (design/sweep_grid.h) and the sentences about a sweep
// (design/sweep_notes.h): one rule for linkwright-cli and the Python module. An error's field
// is the neutral key; its message spells the fields as the caller does.

#include "kinematics/design/sweep_grid.h"
#include "kinematics/design/sweep_notes.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

const GridFieldNames kOptions{"--rpm", "--omega", "--alpha", "--from", "--to", "--step", "--samples", "--law"};
const GridFieldNames kKeywords{"", "omega", "alpha", "start_deg", "stop_deg", "", "samples", ""};

}  // namespace

TEST_CASE("an empty request is the source's own grid", "[sweep_grid]") {
  const auto example = findExample("thesis-crank-rocker");
  REQUIRE(example);
  const SweepGrid grid = sweepGridOf(*example);
  const auto spec = sweepGridSpec({}, grid, kOptions);
  REQUIRE(spec.ok());
  CHECK(spec->omega == example->omega);
  CHECK(spec->fromAngle == degToRad(example->fromDeg));
  CHECK(spec->samples ==
        static_cast<std::size_t>(std::floor((example->toDeg - example->fromDeg) / example->stepDeg + 1e-9)) + 1);
}

TEST_CASE("a refusal names the neutral key and spells the fields as the caller does", "[sweep_grid]") {
  SweepGridRequest request;
  request.start = 90;
  request.stop = 10;
  const auto cli = sweepGridSpec(request, {}, kOptions);
  REQUIRE_FALSE(cli.ok());
  CHECK(cli.error().field == "stop");
  CHECK(cli.error().message == "--to must not be less than --from (got --from 90, --to 10)");
  const auto python = sweepGridSpec(request, {}, kKeywords);
  REQUIRE_FALSE(python.ok());
  CHECK(python.error().field == "stop");
  CHECK(python.error().message == "stop_deg must not be less than start_deg (got start_deg 90, stop_deg 10)");

  SweepGridRequest fast;
  fast.omega = INFINITY;
  const auto e = checkGridRequest(fast, InputKind::Angle, kKeywords);
  REQUIRE(e);
  CHECK(e->field == "omega");
  CHECK(e->message.rfind("omega ", 0) == 0);
}

TEST_CASE("without a step of its own the way out of a step too small is a sample count", "[sweep_grid]") {
  SweepGrid fine;
  fine.stepDeg = 1e-6;
  const auto cli = sweepGridSpec({}, fine, kOptions);
  REQUIRE_FALSE(cli.ok());
  CHECK(cli.error().field == "step");
  CHECK(cli.error().message.rfind("--step is too small: it would give ", 0) == 0);
  const auto python = sweepGridSpec({}, fine, kKeywords);
  REQUIRE_FALSE(python.ok());
  CHECK(python.error().field == "samples");
  CHECK(python.error().message.rfind("samples is needed: the linkage's step would give ", 0) == 0);
}

TEST_CASE("a step too small to count its rows in a double says how many rows, not undefined", "[sweep_grid]") {
  SweepGridRequest request;
  request.step = 1e-320;  // 360° / 1e-320 is beyond a double
  const auto cli = sweepGridSpec(request, {}, kOptions);
  REQUIRE_FALSE(cli.ok());
  CHECK(cli.error().field == "step");
  CHECK(cli.error().message == "--step is too small: it would give about 3.6e322 rows (at most 10000000)");
  request.step = 1e-9;  // a count a double holds: as it is
  const auto counted = sweepGridSpec(request, {}, kOptions);
  REQUIRE_FALSE(counted.ok());
  CHECK(counted.error().message == "--step is too small: it would give 3.6e+11 rows (at most 10000000)");
  SweepGrid fine;
  fine.stepDeg = 1e-320;
  const auto python = sweepGridSpec({}, fine, kKeywords);
  REQUIRE_FALSE(python.ok());
  CHECK(python.error().message ==
        "samples is needed: the linkage's step would give about 3.6e322 rows (at most 10000000)");
}

TEST_CASE("a motion law in time refuses a range, pointing to a law only where one can be given", "[sweep_grid]") {
  std::optional<Example> timed;
  for (const Example& x : examples())
    if (x.time) timed = x;
  REQUIRE(timed);
  SweepGridRequest request;
  request.start = 0;
  const auto cli = sweepGridSpec(request, sweepGridOf(*timed), kOptions);
  REQUIRE_FALSE(cli.ok());
  CHECK(cli.error().field == "start");
  CHECK(cli.error().message ==
        "--from does not apply: this linkage's driver follows a motion law in time (give --law to replace it)");
  const auto python = sweepGridSpec(request, sweepGridOf(*timed), kKeywords);
  REQUIRE_FALSE(python.ok());
  CHECK(python.error().message == "start_deg does not apply: this linkage's driver follows a motion law in time");
}

TEST_CASE("rows left out name a four-bar's exact range, toggles their links", "[sweep_notes]") {
  const auto m = makeFourBar({60, 40, 30, 45}, Branch::Open);
  REQUIRE(m.ok());
  SweepGridRequest request;
  request.start = 0;
  request.stop = 359;
  request.samples = 360;
  const auto spec = sweepGridSpec(request, {}, kOptions);
  REQUIRE(spec.ok());
  const auto summary = sweepInWindows(*m, *spec, {}, 4096, [](const SweepResult&, std::size_t) { return true; });
  REQUIRE(summary.ok());
  const std::vector<std::string> note = notAssembledNote(*m, *summary);
  REQUIRE(note.size() >= 2);
  CHECK(note.front().rfind("the linkage cannot be assembled at ", 0) == 0);
  CHECK(note.front().ends_with("; those rows are left out."));
  CHECK(note.back().rfind("It can be assembled for crank angles ", 0) == 0);
  CHECK(note.back().ends_with(" (exact)."));
  const std::vector<std::string> all = sweepNoteSentences(*m, *summary);
  REQUIRE_FALSE(all.empty());
  CHECK(all.back().rfind(note.front() + " ", 0) == 0);
  CHECK(all.back().ends_with(note.back()));

  const auto toggling = makeFourBar({40, 20, 40, 20}, Branch::Open);
  REQUIRE(toggling.ok());
  CHECK(toggleNote(*toggling, 0.0) ==
        "toggle position at crank angle 0°: coupler and rocker are collinear, ω and α are undefined (cells left "
        "empty)");
}
