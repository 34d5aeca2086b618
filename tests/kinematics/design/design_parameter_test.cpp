// Setting a design's parameter (design/design_parameter.h): lengthening the path of seed 004's
// arm moves the end of its time base and of its grid to the new path's end, so the whole path
// is analysed (issue 57 item 8: 0.424 m of a 0.68 m path were). A drive that stopped short of
// the end stays where it was; a parameter off the path changes neither.

#include "kinematics/design/design_parameter.h"

#include "kinematics/model/path_shape.h"
#include "kinematics/solve/motion_law.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <variant>

using namespace linkwright::kinematics;

namespace {

Design arm() {
  const std::optional<Design> d = designForExample("seed-arm");
  REQUIRE(d.has_value());
  REQUIRE(d->time.has_value());
  return *d;
}

Parameter slotOf(const Mechanism& m, ParameterSlot slot, std::size_t vertex) {
  const std::vector<Parameter> all = parametersOf(m);
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const Parameter& p) { return p.slot == slot && p.vertex == vertex; });
  REQUIRE(it != all.end());
  return *it;
}

double pathEndLength(const Design& d) {
  for (const Point& p : d.mechanism.points)
    if (const auto* path = std::get_if<PathPoint>(&p.definition)) return pathLength(path->path);
  FAIL("no driven path");
  return 0.0;
}

}  // namespace

TEST_CASE("lengthening an arm's path moves its time base and grid to the new end", "[design][parameters]") {
  Design d = arm();
  const double speed = 2.0;  // m/s, the example's constant velocity
  REQUIRE(d.time->toTime == Approx(std::sqrt(0.18) / speed).epsilon(1e-12));
  // The end vertex from (0, 0.3) to (−0.2, 0.6): the path is now √(0.25 + 0.36) m long.
  REQUIRE(setDesignParameter(d, slotOf(d.mechanism, ParameterSlot::PathX, 1), -0.2));
  REQUIRE(setDesignParameter(d, slotOf(d.mechanism, ParameterSlot::PathY, 1), 0.6));
  const double length = std::sqrt(0.25 + 0.36);
  CHECK(pathEndLength(d) == Approx(length).epsilon(1e-15));
  CHECK(d.time->toTime == Approx(length / speed).epsilon(1e-12));
  CHECK(motionAt(d.time->law, d.time->toTime).position == Approx(length).epsilon(1e-12));
  CHECK(d.toDeg == Approx(length).epsilon(1e-15));
  CHECK(d.time->fromTime == 0.0);

  // Shortened back: the ends follow again.
  REQUIRE(setDesignParameter(d, slotOf(d.mechanism, ParameterSlot::PathX, 1), 0.0));
  REQUIRE(setDesignParameter(d, slotOf(d.mechanism, ParameterSlot::PathY, 1), 0.3));
  CHECK(d.time->toTime == Approx(std::sqrt(0.18) / speed).epsilon(1e-12));
  CHECK(d.toDeg == Approx(std::sqrt(0.18)).epsilon(1e-15));
}

TEST_CASE("a drive that stops short of the path's end, or an edit off the path, keeps its ends",
          "[design][parameters]") {
  Design d = arm();
  d.time->toTime *= 0.5;
  d.toDeg *= 0.5;
  const Design shortRun = d;
  REQUIRE(setDesignParameter(d, slotOf(d.mechanism, ParameterSlot::PathY, 1), 0.6));
  CHECK(d.time->toTime == shortRun.time->toTime);
  CHECK(d.toDeg == shortRun.toDeg);

  Design e = arm();
  const Design before = e;
  const std::vector<Parameter> all = parametersOf(e.mechanism);
  const auto length =
      std::find_if(all.begin(), all.end(), [](const Parameter& p) { return p.slot == ParameterSlot::Length; });
  REQUIRE(length != all.end());
  REQUIRE(setDesignParameter(e, *length, 0.35));
  CHECK(e.time == before.time);
  CHECK(e.toDeg == before.toDeg);
  CHECK(e.mechanism != before.mechanism);
}
