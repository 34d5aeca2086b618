// Tests kinematics/synthesis/path_start_blocks.cpp: a block of another search, or one whose
// counts or minima do not fit its search (as a pickled block can be), is refused with a
// sentence before anything of it is read; the search's own blocks still merge.

#include "kinematics/synthesis/path_generation.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <functional>
#include <limits>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;

namespace {

std::vector<Eigen::Vector2d> thesisCurve(const std::vector<double>& crankAnglesDeg) {
  const auto m = makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0});
  REQUIRE(m.ok());
  std::vector<Eigen::Vector2d> points;
  for (const double deg : crankAnglesDeg) {
    const auto pose = solvePose(*m, {degToRad(deg), 0.0, 0.0});
    REQUIRE(pose.ok());
    points.push_back(pose->position[fourbar::kCouplerPoint.index]);
  }
  return points;
}

}  // namespace

TEST_CASE("A block that is not the search's is refused before it is merged", "[synthesis][path][errors]") {
  const PathTarget target{thesisCurve({10.0, 50.0, 100.0, 160.0, 220.0, 280.0})};
  PathOptions options;
  options.starts = 150;  // blocks 0 and 1 (50 starts)
  options.keep = 4;
  auto block = runPathStartBlock(target, options, 1);
  REQUIRE(block.ok());
  REQUIRE_FALSE(block->kept.empty());
  CHECK(block->search == pathSearchFingerprint(target, options));
  REQUIRE(pathSynthesisFromBlocks(target, options, {}, {*block}).ok());

  const auto refusal = [&](const PathTarget& t, const PathOptions& o, const PathStartBlock& b) {
    const auto merged = pathSynthesisFromBlocks(t, o, {}, {b});
    REQUIRE_FALSE(merged.ok());
    CHECK(merged.error().field == "blocks");
    return merged.error().message;
  };
  const std::string another =
      "block 1 cannot be merged: it is a block of another search (other targets, timing or options), not of this one";
  // Another search's block: fewer targets (its minima's crank angles would be read past), a
  // target moved by an ulp, another seed.
  PathTarget five = target;
  five.points.pop_back();
  CHECK(refusal(five, options, *block) == another);
  PathTarget moved = target;
  moved.points[2].x() = std::nextafter(moved.points[2].x(), 1e9);
  CHECK(refusal(moved, options, *block) == another);
  PathOptions seeded = options;
  seeded.seed += 1;
  CHECK(refusal(target, seeded, *block) == another);

  // The search's fingerprint on a block that does not fit it (an edited pickle).
  const auto edited = [&](const std::function<void(PathStartBlock&)>& edit) {
    PathStartBlock b = *block;
    edit(b);
    return refusal(target, options, b);
  };
  CHECK(edited([](PathStartBlock& b) { b.startsRun = 51; }) ==
        "block 1 cannot be merged: it says it ran 51 starts, but the block has 0 to 50");
  CHECK(edited([](PathStartBlock& b) { b.startsNotAssembled = -1; }) ==
        "block 1 cannot be merged: it says -1 starts did not assemble, but it ran 50");
  CHECK(edited([](PathStartBlock& b) {
          while (b.kept.size() < 5) b.kept.push_back(b.kept.front());
        }) == "block 1 cannot be merged: it keeps 5 minima, more than its " +
                  std::to_string(block->startsRun - block->startsNotAssembled) +
                  " assembled starts or the search's keep of 4");
  CHECK(edited([](PathStartBlock& b) { b.kept.front().start = 3; }) ==
        "block 1 cannot be merged: a minimum comes from start 3, not one of the block's starts 100 to 149");
  const std::string from = std::to_string(block->kept.front().start);
  CHECK(edited([](PathStartBlock& b) { b.kept.front().crankAngles.clear(); }) ==
        "block 1 cannot be merged: the minimum from start " + from +
            " has 0 crank angles, not one for each of the 6 targets");
  CHECK(edited([](PathStartBlock& b) { b.kept.front().crankAngles.push_back(0.5); }) ==
        "block 1 cannot be merged: the minimum from start " + from +
            " has 7 crank angles, not one for each of the 6 targets");
  CHECK(edited([](PathStartBlock& b) { b.kept.front().coupler = std::numeric_limits<double>::quiet_NaN(); }) ==
        "block 1 cannot be merged: the minimum from start " + from + " holds a number that is not finite");
  CHECK(edited([](PathStartBlock& b) { b.block = 2; }) == "a block numbered 2 is not one of this search's 0 to 1");
}

TEST_CASE("A search's fingerprint is a function of its targets and options alone", "[synthesis][path]") {
  const PathTarget target{thesisCurve({10.0, 50.0, 100.0, 160.0, 220.0})};
  PathOptions options;
  CHECK(pathSearchFingerprint(target, options) == pathSearchFingerprint(PathTarget(target), PathOptions(options)));
  for (const auto& change : std::vector<std::function<void(PathTarget&, PathOptions&)>>{
           [](PathTarget&t, PathOptions&) {
             t.timing = {0.0, 0.1, 0.2, 0.3, 0.4};
           },
           [](PathTarget&t, PathOptions&) { t.needsFullRotation = true; },
           [](PathTarget&t, PathOptions&) { t.lengthUnit = "in"; }, [](PathTarget&, PathOptions&o) { o.starts += 1; },
           [](PathTarget&, PathOptions&o) { o.keep += 1; },
           [](PathTarget&, PathOptions&o) { o.maxEvaluations += 1; }}) {
    PathTarget t = target;
    PathOptions o = options;
    change(t, o);
    CHECK(pathSearchFingerprint(t, o) != pathSearchFingerprint(target, options));
  }
}
