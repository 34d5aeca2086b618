// Tests kinematics/synthesis/path_generation.h: targets taken from a known four-bar's coupler
// curve are recovered; every candidate's reported distances are those the pose solver gives at
// its crank angles; prescribed timing is met; the search repeats exactly for a seed, reports
// progress, stops when cancelled with what it found; bad targets are errors naming the field.

#include "kinematics/synthesis/path_generation.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <atomic>
#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {

// The thesis crank-rocker (frame 60, crank 25, coupler 70, rocker 45 mm) with a coupler point
// 35 mm along and 20 mm across the coupler: its coupler point at the given crank angles (deg).
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

// Solves the candidate's design at its crank angles: the distances to the targets.
std::vector<double> solvedDistances(const PathCandidate& c, const std::vector<Eigen::Vector2d>& targets) {
  std::vector<double> d;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto pose = solvePose(c.candidate.design.mechanism, {c.crankAngles[i], 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    d.push_back((pose->position[fourbar::kCouplerPoint.index] - targets[i]).norm());
  }
  return d;
}

// Every candidate's reported distances are the pose solver's, and the list is sorted.
void checkReportedDistances(const PathSynthesis& s, const std::vector<Eigen::Vector2d>& targets) {
  for (std::size_t k = 0; k < s.candidates.size(); ++k) {
    CAPTURE(k);
    const PathCandidate& c = s.candidates[k];
    const std::vector<double> d = solvedDistances(c, targets);
    double worst = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      CHECK(c.distances[i] == within(d[i], 1e-9 * s.scale));
      worst = std::max(worst, d[i]);
    }
    CHECK(c.worstDistance == within(worst, 1e-9 * s.scale));
    CHECK(c.candidate.error == c.worstDistance);
    if (k > 0) CHECK(s.candidates[k - 1].worstDistance <= c.worstDistance);
  }
}

}  // namespace

TEST_CASE("Six points on a known coupler curve are recovered", "[synthesis][path]") {
  const auto targets = thesisCurve({0.0, 60.0, 120.0, 180.0, 240.0, 300.0});
  const auto s = synthesisePath({targets});
  REQUIRE(s.ok());
  REQUIRE_FALSE(s->candidates.empty());
  CHECK_FALSE(s->cancelled);
  CHECK(s->startsRun == kDefaultPathStarts);
  const PathCandidate& best = s->candidates.front();
  CAPTURE(best.worstDistance, s->scale);
  // Six points are fewer than the nine a four-bar can pass through: an exact fit exists (the
  // thesis linkage), so LM converges to it; 1e-6 of the scale is far above LM's round-off.
  CHECK(best.worstDistance <= 1e-6 * s->scale);
  checkReportedDistances(*s, targets);
  const auto fourBar = asFourBar(best.candidate.design.mechanism);
  REQUIRE(fourBar.has_value());
  CHECK(fourBar->lengths == best.lengths);
}

TEST_CASE("Morgan & Wampler's five points on a straight line are passed exactly", "[synthesis][path][published]") {
  // Morgan & Wampler, "Solving a planar four-bar design problem using continuation", J. Mech.
  // Des. 112 (1990) 544–550, Problem 7: five precision points on the line y = x + 0.56
  // (coordinates as copied into PHCpack's documentation, phcpy "the design of a 4-bar
  // mechanism"). With the pivots fixed at (0, 0) and (1, 0) continuation finds 15 real
  // four-bars whose coupler point passes through all five exactly: the published error is 0.
  // Our pivots are free (a wider search), so an exact fit must be found too; 1e-6 of the
  // scale stands for 0 (LM stops near 1e-12 of it).
  const std::vector<Eigen::Vector2d> targets{{0.50, 1.06}, {-0.83, -0.27}, {-0.34, 0.22}, {-0.13, 0.43}, {0.22, 0.78}};
  PathOptions options;
  options.starts = 100;
  const auto s = synthesisePath({targets}, options);
  REQUIRE(s.ok());
  REQUIRE_FALSE(s->candidates.empty());
  CHECK(s->candidates.front().worstDistance <= 1e-6 * s->scale);
  checkReportedDistances(*s, targets);
}

TEST_CASE("Prescribed timing is met", "[synthesis][path][timing]") {
  // The thesis curve at crank angles 30°, 70°, …, 230° (frame-relative, frame along +x).
  std::vector<double> deg{30.0, 70.0, 110.0, 150.0, 190.0, 230.0};
  const auto targets = thesisCurve(deg);
  PathTarget t{targets};
  for (const double d : deg) t.timing.push_back(degToRad(d));
  for (const TimingReference reference : {TimingReference::Start, TimingReference::Frame}) {
    CAPTURE(static_cast<int>(reference));
    t.timingReference = reference;
    PathOptions options;
    options.starts = 100;
    const auto s = synthesisePath(t, options);
    REQUIRE(s.ok());
    REQUIRE_FALSE(s->candidates.empty());
    const PathCandidate& best = s->candidates.front();
    CHECK(best.worstDistance <= 1e-6 * s->scale);
    checkReportedDistances(*s, targets);
    // The crank turns between targets by the prescribed differences.
    for (std::size_t i = 1; i < deg.size(); ++i)
      CHECK(angleDifference(best.crankAngles[i] - best.crankAngles[0], t.timing[i] - t.timing[0]) ==
            within(0.0, 1e-12));
    if (reference == TimingReference::Frame) {
      const double beta = std::atan2(best.o4.y() - best.o2.y(), best.o4.x() - best.o2.x());
      for (std::size_t i = 0; i < deg.size(); ++i)
        CHECK(angleDifference(best.crankAngles[i] - beta, t.timing[i]) == within(0.0, 1e-12));
    }
  }
}

TEST_CASE("The search repeats for a seed and reports its progress", "[synthesis][path]") {
  const auto targets = thesisCurve({10.0, 50.0, 100.0, 160.0, 220.0});
  PathOptions options;
  options.starts = 20;
  int calls = 0, lastDone = 0;
  const auto a = synthesisePath({targets}, options, {}, nullptr, [&](int done, int total) {
    ++calls;
    CHECK(total == 20);
    CHECK(done == lastDone + 1);
    lastDone = done;
  });
  const auto b = synthesisePath({targets}, options);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(calls == 20);
  REQUIRE(a->candidates.size() == b->candidates.size());
  for (std::size_t k = 0; k < a->candidates.size(); ++k) {
    CHECK(a->candidates[k].candidate == b->candidates[k].candidate);
    CHECK(a->candidates[k].start == b->candidates[k].start);
  }
  checkReportedDistances(*a, targets);
}

TEST_CASE("Blocks of starts run apart and merged give the search's answer to the last bit", "[synthesis][path]") {
  const auto targets = thesisCurve({10.0, 50.0, 100.0, 160.0, 220.0, 280.0});
  PathOptions options;
  options.starts = 2 * kPathStartsPerBlock + 17;  // a short last block
  options.keep = 6;
  const auto whole = synthesisePath({targets}, options);
  REQUIRE(whole.ok());
  REQUIRE(pathStartBlockCount(options) == 3);
  // Run in reverse order, as a cluster may finish them, each block alone.
  std::vector<PathStartBlock> blocks;
  for (int b = 2; b >= 0; --b) {
    auto block = runPathStartBlock({targets}, options, b);
    REQUIRE(block.ok());
    CHECK(block->startsRun == (b == 2 ? 17 : kPathStartsPerBlock));
    for (const PathMinimum& m : block->kept) CHECK(m.start / kPathStartsPerBlock == b);
    blocks.push_back(std::move(block).value());
  }
  const auto split = pathSynthesisFromBlocks({targets}, options, {}, blocks);
  REQUIRE(split.ok());
  CHECK(split->startsRun == whole->startsRun);
  CHECK(split->startsNotAssembled == whole->startsNotAssembled);
  CHECK_FALSE(split->cancelled);
  REQUIRE(split->candidates.size() == whole->candidates.size());
  REQUIRE(whole->candidates.size() >= 2);
  for (std::size_t k = 0; k < whole->candidates.size(); ++k) {
    CAPTURE(k);
    CHECK(split->candidates[k].candidate == whole->candidates[k].candidate);
    CHECK(split->candidates[k].start == whole->candidates[k].start);
    CHECK(split->candidates[k].distances == whole->candidates[k].distances);
    CHECK(split->candidates[k].crankAngles == whole->candidates[k].crankAngles);
  }
  // A start depends on the seed and its index alone: block 1 of a longer search is the same.
  PathOptions longer = options;
  longer.starts = 10 * kPathStartsPerBlock;
  const auto again = runPathStartBlock({targets}, longer, 1);
  REQUIRE(again.ok());
  REQUIRE(again->kept.size() == blocks[1].kept.size());
  for (std::size_t k = 0; k < again->kept.size(); ++k) {
    CHECK(again->kept[k].start == blocks[1].kept[k].start);
    CHECK(again->kept[k].worst == blocks[1].kept[k].worst);
    CHECK(again->kept[k].crankAngles == blocks[1].kept[k].crankAngles);
  }
  // A block missing is a search cut short; one outside the search or given twice is refused.
  blocks.pop_back();
  const auto partial = pathSynthesisFromBlocks({targets}, options, {}, blocks);
  REQUIRE(partial.ok());
  CHECK(partial->cancelled);
  CHECK(partial->startsRun == kPathStartsPerBlock + 17);
  blocks.push_back(blocks.front());
  const auto twice = pathSynthesisFromBlocks({targets}, options, {}, blocks);
  REQUIRE_FALSE(twice.ok());
  CHECK(twice.error().message == "block 2 is given twice");
  const auto outside = runPathStartBlock({targets}, options, 3);
  REQUIRE_FALSE(outside.ok());
  CHECK(outside.error().field == "block");
  CHECK(outside.error().message == "block must be between 0 and 2 (got 3)");
}

TEST_CASE("Cancelling returns what was found so far", "[synthesis][path]") {
  const auto targets = thesisCurve({0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0});
  std::atomic<bool> cancel{false};
  PathOptions options;
  options.starts = 1000;
  const auto s = synthesisePath({targets}, options, {}, &cancel, [&](int done, int) {
    if (done == 5) cancel = true;
  });
  REQUIRE(s.ok());
  CHECK(s->cancelled);
  CHECK(s->startsRun == 5);
  CHECK(s->candidates.size() + static_cast<std::size_t>(s->startsNotAssembled) >= 1);
  CHECK(s->candidates.size() <= 5);
  for (const PathCandidate& c : s->candidates) CHECK(c.start < 5);
  checkReportedDistances(*s, targets);
}

TEST_CASE("Candidates carry their defects", "[synthesis][path][defects]") {
  const auto targets = thesisCurve({0.0, 60.0, 120.0, 180.0, 240.0, 300.0});
  PathTarget t{targets};
  t.needsFullRotation = true;
  PathOptions options;
  options.starts = 60;
  const auto s = synthesisePath(t, options);
  REQUIRE(s.ok());
  for (const PathCandidate& c : s->candidates) {
    REQUIRE(c.candidate.grashof.has_value());
    CHECK(c.candidate.has(DefectKind::NotGrashof) == !c.candidate.grashof->inputFullyRotates);
    for (const Defect& d : c.candidate.defects) CHECK_FALSE(d.message.empty());
    // The design's grid covers the targets' crank angles.
    CHECK(c.candidate.design.toDeg > c.candidate.design.fromDeg);
    for (const double l : {c.lengths.frame, c.lengths.crank, c.lengths.coupler, c.lengths.rocker}) {
      CHECK(l >= 1e-2 * s->scale * (1.0 - 1e-12));
      CHECK(l <= 10.0 * s->scale * (1.0 + 1e-12));
    }
  }
}

TEST_CASE("Bad path targets are errors naming the field", "[synthesis][path][errors]") {
  const auto targets = thesisCurve({0.0, 60.0, 120.0, 180.0, 240.0, 300.0});
  const auto field = [](const PathTarget& t, const PathOptions& o = {}) {
    const auto r = synthesisePath(t, o);
    REQUIRE_FALSE(r.ok());
    CHECK_FALSE(r.error().message.empty());
    return r.error().field;
  };
  CHECK(field({{targets[0], targets[1], targets[2]}}) == "points");
  auto many = targets;
  many.insert(many.end(), targets.begin(), targets.end());
  CHECK(field({many}) == "points");
  auto nan = targets;
  nan[2].y() = NAN;
  CHECK(field({nan}) == "points[2].y");
  auto twice = targets;
  twice[4] = twice[1];
  CHECK(field({twice}) == "points[4]");
  PathTarget timed{targets, {0.0, 1.0, 2.0}};
  CHECK(field(timed) == "timing");
  timed.timing = {0.0, 1.0, 2.0, 3.0, 4.0, INFINITY};
  CHECK(field(timed) == "timing[5]");
  timed.timing = {0.0, 1.0, 2.0, 3.0, 4.0, 1.0 + 2.0 * kPi};
  CHECK(field(timed) == "timing[5]");
  PathOptions o;
  o.starts = 0;
  CHECK(field({targets}, o) == "starts");
  o = {};
  o.keep = 0;
  CHECK(field({targets}, o) == "keep");
  o = {};
  o.maxEvaluations = 1;
  CHECK(field({targets}, o) == "maxEvaluations");
}

TEST_CASE("Collinear targets are a valid task", "[synthesis][path]") {
  // A straight-line path is what Watt's and Chebyshev's linkages were invented for: not an
  // error, and an approximate straight-line four-bar is found.
  std::vector<Eigen::Vector2d> line;
  for (int i = 0; i < 5; ++i) line.emplace_back(10.0 * i, 5.0 * i);
  PathOptions options;
  options.starts = 50;
  const auto s = synthesisePath({line}, options);
  REQUIRE(s.ok());
  REQUIRE_FALSE(s->candidates.empty());
  checkReportedDistances(*s, line);
  CHECK(s->candidates.front().worstDistance <= 1e-2 * s->scale);
}
