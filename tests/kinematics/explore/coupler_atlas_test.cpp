// Tests kinematics/explore/coupler_atlas.h and atlas_filter.h: every curve the atlas gives is the
// solver's coupler path for its linkage, sample by sample (a crank that turns fully, and one
// that rocks, traced on both branches); the grid's numbering; a design made from a cell; the
// filters; cancelling; and the refusals of bad axes, each as a sentence.

#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/explore/atlas_filter.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <atomic>
#include <cmath>

using namespace linkwright::kinematics;

namespace {

// The solver's path of P over `spec` for the cell's four-bar on `branch`, with no atlas code
// between: makeFourBar and sweep().
SweepResult solverPath(const AtlasCellKey& key, Branch branch, const SweepSpec& spec) {
  const double c = key.lengths.coupler;
  const auto m = makeFourBar(key.lengths, branch, "mm", CouplerPointSpec{key.point.along * c, key.point.across * c});
  REQUIRE(m.ok());
  auto s = sweep(*m, spec);
  REQUIRE(s.ok());
  return std::move(s).value();
}

SweepSpec grid(double from, double to, std::size_t samples) {
  SweepSpec spec;
  spec.fromAngle = from;
  spec.toAngle = to;
  spec.samples = samples;
  spec.omega = 1.0;
  return spec;
}

// The curve's samples [first, first + count) against the sweep's, forwards or backwards.
void requireSameSamples(const CouplerCurve& curve, std::size_t first, const SweepResult& s, bool backwards) {
  const std::size_t p = fourbar::kCouplerPoint.index;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::size_t j = backwards ? s.size() - 1 - k : k;
    REQUIRE(s.assembled(j));
    CAPTURE(first + k, s.inputAngle[j]);
    REQUIRE(curve.crankAngle[first + k] == s.inputAngle[j]);
    REQUIRE(curve.point[first + k] == s.position[p][j]);
    if (s.ok(j) && curve.rateOk[first + k]) REQUIRE(curve.derivative[first + k] == s.velocity[p][j]);
  }
}

}  // namespace

TEST_CASE("every atlas curve is the solver's coupler path of its four-bar, sample by sample", "[atlas]") {
  AtlasAxes axes;
  axes.coupler = {2.0, 3.5};
  axes.rocker = {2.5};
  // Frame 3 turns the crank; frame 6 with coupler 3.5 rocks it (1 + 6 > 3.5 + 2.5), with coupler 2
  // never assembles (1 + 2 + 2.5 < 6).
  axes.frame = {3.0, 6.0};
  axes.along = {0.5, 1.5};
  axes.across = {-0.5, 0.8};
  axes.samples = 120;
  const auto page = computeAtlasPage(axes, 0, atlasCellCount(axes));
  REQUIRE(page.ok());
  REQUIRE(page->size() == 16);
  std::size_t turning = 0, rocking = 0, never = 0;
  for (const AtlasCell& cell : *page) {
    CAPTURE(cell.key.lengths.coupler, cell.key.lengths.frame, cell.key.point.along, cell.key.point.across);
    const InputRange range = fourBarInputRange(cell.key.lengths);
    if (cell.motion == CrankMotion::NeverAssembles) {
      ++never;
      CHECK(!range.fullRotation);
      CHECK(range.ranges.empty());
      CHECK(cell.curve.size() == 0);
      continue;
    }
    if (cell.motion == CrankMotion::FullTurn) {
      ++turning;
      REQUIRE(range.fullRotation);
      const auto s = solverPath(cell.key, Branch::Open, grid(0.0, 2.0 * kPi * 119.0 / 120.0, 120));
      REQUIRE(cell.curve.size() == 120);
      requireSameSamples(cell.curve, 0, s, false);
    } else {
      ++rocking;
      REQUIRE(!range.fullRotation);
      const AngleRange& r = range.ranges.front();
      // Across the range on the cell's branch, then back on the other, at θ = c − r cos u: each
      // sample the solver's pose there, on that branch.
      const double c = 0.5 * (r.from + r.to), half = 0.5 * (r.to - r.from);
      REQUIRE(cell.curve.size() == 120);
      const double ac = cell.key.lengths.coupler;
      for (std::size_t k = 0; k < 120; ++k) {
        const double u = 2.0 * kPi * (static_cast<double>(k) + 0.5) / 120.0;
        const Branch branch = u < kPi ? Branch::Open : Branch::Crossed;
        const auto m = makeFourBar(cell.key.lengths, branch, "mm",
                                   CouplerPointSpec{cell.key.point.along * ac, cell.key.point.across * ac});
        REQUIRE(m.ok());
        const auto pose = solvePose(*m, {c - half * std::cos(u), 1.0, 0.0});
        REQUIRE(pose.ok());
        CAPTURE(k);
        REQUIRE(cell.curve.parameter[k] == u);
        REQUIRE(cell.curve.crankAngle[k] == c - half * std::cos(u));
        REQUIRE(cell.curve.point[k] == pose->position[fourbar::kCouplerPoint.index]);
        REQUIRE((cell.curve.derivative[k] - pose->velocity[fourbar::kCouplerPoint.index] * half * std::sin(u)).norm() <=
                1e-12 * cell.features.size);
      }
      // The two branches meet at the range's edges: the curve closes without a jump.
      CHECK((cell.curve.point[59] - cell.curve.point[60]).norm() < 0.1 * cell.features.size);
      CHECK((cell.curve.point[119] - cell.curve.point[0]).norm() < 0.1 * cell.features.size);
    }
    CHECK(cell.curve.closed);
    CHECK(cell.grashof == classifyGrashof(cell.key.lengths));
  }
  CHECK(turning > 0);
  CHECK(rocking > 0);
  CHECK(never > 0);
}

// A change-point linkage (1 + 2 = 1.5 + 1.5) folds flat at θ = π, where its two branches meet.
// Its sweep carries on into the other branch there, so over one turn its curve did not close: the
// jump at the turn's end was classified as a straight run or spoilt the mirror, and whether a
// sample fell on π (an even count) changed the answer. Held on its branch, the curve is the
// solver's pose at each angle, closes, and has the same features at 360, 361 and 1440 samples.
TEST_CASE("a change-point cell traces its branch's closed curve, with the same features at any sample count",
          "[atlas]") {
  AtlasAxes axes;
  axes.coupler = {1.5};
  axes.rocker = {1.5};
  axes.frame = {2.0};
  axes.along = {0.5, 2.0};
  axes.across = {0.0, 0.5};
  const auto featureSet = [](const CurveFeatures& f) {
    return std::vector<std::size_t>{f.cusps.size(), f.crunodes.size(), f.symmetry ? 1u : 0u, f.straight ? 1u : 0u,
                                    f.circular ? 1u : 0u};
  };
  std::vector<std::vector<std::size_t>> first;
  for (const std::size_t samples : {std::size_t{360}, std::size_t{361}, std::size_t{1440}}) {
    CAPTURE(samples);
    axes.samples = samples;
    const auto page = computeAtlasPage(axes, 0, atlasCellCount(axes));
    REQUIRE(page.ok());
    for (std::size_t i = 0; i < page->size(); ++i) {
      const AtlasCell& cell = (*page)[i];
      CAPTURE(cell.key.point.along, cell.key.point.across);
      REQUIRE(cell.grashof.category == GrashofClass::ChangePoint);
      REQUIRE(cell.motion == CrankMotion::FullTurn);
      REQUIRE(cell.curve.size() == samples);
      const auto m = atlasMechanism(cell.key, Branch::Open);
      REQUIRE(m.ok());
      Pose pose;
      preparePose(*m, pose);
      for (std::size_t k = 0; k < samples; ++k) {
        // At π the pose is singular (its rates undefined), but placed.
        REQUIRE(solvePoseInto(*m, {cell.curve.crankAngle[k], 1.0, 0.0}, SolveRequest{}, pose).status !=
                PoseStatus::NotAssemblable);
        REQUIRE(cell.curve.point[k] == pose.position[fourbar::kCouplerPoint.index]);
      }
      // No jump where the turn closes: the last sample is as near the first as neighbours are.
      CHECK((cell.curve.point.back() - cell.curve.point.front()).norm() < 0.05 * cell.features.size);
      if (first.size() <= i) first.push_back(featureSet(cell.features));
      else CHECK(featureSet(cell.features) == first[i]);
    }
  }
}

TEST_CASE("atlas cells are numbered coupler slowest and across fastest", "[atlas]") {
  AtlasAxes axes;
  axes.coupler = {2.0, 3.0};
  axes.rocker = {1.5, 2.5, 3.5};
  axes.frame = {2.0};
  axes.along = {0.0, 1.0};
  axes.across = {0.25, 0.5, 0.75};
  REQUIRE(atlasCellCount(axes) == 36);
  const AtlasCellKey k = atlasCellKey(axes, 1 * 18 + 2 * 6 + 0 * 6 + 1 * 3 + 2);
  CHECK(k.lengths == FourBarLengths{2.0, 1.0, 3.0, 3.5});
  CHECK(k.point == CouplerPointSpec{1.0, 0.75});
  CHECK(k.samples == axes.samples);
  CHECK(k.branch == Branch::Open);
}

TEST_CASE("an atlas cell becomes a four-bar design with its point P, scaled to the crank asked", "[atlas]") {
  AtlasCellKey key;
  key.lengths = {2.0, 1.0, 2.5, 2.5};
  key.point = {2.0, 0.0};
  const auto design = atlasCellDesign(key, 20.0, "mm");
  REQUIRE(design.ok());
  const auto fourBar = asFourBar(design->mechanism);
  REQUIRE(fourBar.has_value());
  CHECK(fourBar->lengths == FourBarLengths{40.0, 20.0, 50.0, 50.0});
  CHECK(design->fromDeg == 0.0);
  CHECK(design->toDeg == 360.0);
  // Its P traces the cell's curve scaled by 20.
  const auto cell = computeAtlasCell(key);
  REQUIRE(cell.ok());
  auto s = sweep(design->mechanism, grid(0.0, 0.0, 1));
  REQUIRE(s.ok());
  const auto p = s->position[fourbar::kCouplerPoint.index][0];
  CHECK((p - 20.0 * cell->curve.point[0]).norm() < 1e-12);

  SECTION("a rocking crank's design runs over its traced range") {
    key.lengths = {4.0, 1.0, 2.0, 2.5};  // 1 + 4 > 2 + 2.5: non-Grashof, the crank rocks
    const auto rocker = computeAtlasCell(key);
    REQUIRE(rocker.ok());
    REQUIRE(rocker->motion == CrankMotion::Rocks);
    const auto d = atlasCellDesign(key);
    REQUIRE(d.ok());
    CHECK(d->fromDeg == Approx(radToDeg(rocker->range.from + kAtlasEdgeMargin)).epsilon(1e-12));
    CHECK(d->toDeg == Approx(radToDeg(rocker->range.to - kAtlasEdgeMargin)).epsilon(1e-12));
  }
  SECTION("a cell that never assembles is refused") {
    key.lengths = {6.0, 1.0, 2.0, 2.5};
    const auto d = atlasCellDesign(key);
    REQUIRE(!d.ok());
    CHECK(d.error().field == "cell");
    CHECK(d.error().message == "this atlas cell's four-bar cannot be assembled at any crank angle");
  }
}

TEST_CASE("atlas filters keep the cells that have every feature asked", "[atlas]") {
  CurveFeatures none, cusp, both;
  cusp.cusps.push_back({1.0, Eigen::Vector2d(1, 2), 0.0});
  both = cusp;
  both.straight = StraightRun{};
  CHECK(matchesFilter(none, AtlasFilter{}));
  CHECK(!matchesFilter(none, AtlasFilter{.cusp = true}));
  CHECK(matchesFilter(cusp, AtlasFilter{.cusp = true}));
  CHECK(!matchesFilter(cusp, AtlasFilter{.cusp = true, .straight = true}));
  CHECK(matchesFilter(both, AtlasFilter{.cusp = true, .straight = true}));
  CHECK(!matchesFilter(both, AtlasFilter{.crunode = true}));
  CHECK(!matchesFilter(both, AtlasFilter{.symmetric = true}));
  CHECK(!matchesFilter(both, AtlasFilter{.circular = true}));

  std::vector<AtlasCell> cells(3);
  cells[0].features = none;
  cells[1].features = both;
  cells[2].features = both;
  cells[2].motion = CrankMotion::NeverAssembles;
  CHECK(filterCells(cells, AtlasFilter{.cusp = true}) == std::vector<std::size_t>{1});
  CHECK(filterCells(cells, AtlasFilter{}) == std::vector<std::size_t>{0, 1, 2});
  // A cell that never assembles has no curve: it matches no feature, even one it was given.
  CHECK(filterCells(cells, AtlasFilter{.straight = true}) == std::vector<std::size_t>{1});
  CHECK(featureNames(both) == std::vector<std::string>{"cusp", "straight"});

  const auto parsed = parseAtlasFilter("crunode,circular");
  REQUIRE(parsed.ok());
  CHECK(*parsed == AtlasFilter{.crunode = true, .circular = true});
  const auto bad = parseAtlasFilter("cusp,loop", "--filter");
  REQUIRE(!bad.ok());
  CHECK(bad.error().field == "--filter");
  CHECK(bad.error().message ==
        "--filter takes cusp, crunode, symmetric, straight or circular, separated by commas (got 'loop')");
}

TEST_CASE("an atlas page stops when cancelled", "[atlas]") {
  std::atomic<bool> cancel{true};
  const auto page = computeAtlasPage(AtlasAxes{}, 0, 10, &cancel);
  REQUIRE(!page.ok());
  CHECK(page.error().code == ErrorCode::Cancelled);
  const auto cell = computeAtlasCell(atlasCellKey(AtlasAxes{}, 0), &cancel);
  REQUIRE(!cell.ok());
  CHECK(cell.error().code == ErrorCode::Cancelled);
}

TEST_CASE("bad atlas axes are refused, naming the axis, the value and the range", "[atlas]") {
  const auto refused = [](AtlasAxes axes) {
    const auto e = checkAtlasAxes(axes);
    REQUIRE(e.has_value());
    return *e;
  };
  AtlasAxes a;
  a.coupler = {};
  CHECK(refused(a).message == "coupler needs at least one value");
  a = {};
  a.rocker = {2.0, -1.0};
  CHECK(refused(a).field == "rocker");
  CHECK(refused(a).message == "rocker ratios must be between 0.001 and 1000 crank lengths (got -1)");
  a = {};
  a.frame = {std::nan("")};
  CHECK(refused(a).message == "frame ratios must be between 0.001 and 1000 crank lengths (got undefined)");
  a = {};
  a.across = {250.0};
  CHECK(refused(a).message == "across must be finite and within ±100 coupler lengths (got 250)");
  a = {};
  a.along = std::vector<double>(65, 1.0);
  CHECK(refused(a).message == "along takes at most 64 values (got 65)");
  a = {};
  a.samples = 10;
  CHECK(refused(a).field == "samples");
  CHECK(refused(a).message == "samples must be between 36 and 100000 (got 10)");
  CHECK(!checkAtlasAxes(AtlasAxes{}).has_value());
  const auto page = computeAtlasPage(a, 0, 1);
  REQUIRE(!page.ok());
  CHECK(page.error().field == "samples");
}

TEST_CASE("an atlas run hands on each cell in order as it is classified, with progress, and stops when asked",
          "[atlas]") {
  AtlasAxes axes;
  axes.samples = 72;
  const auto page = computeAtlasPage(axes, 5, 12);
  REQUIRE(page.ok());
  std::vector<std::size_t> seen, progress;
  RunControl control;
  control.progress = [&](std::size_t done, std::size_t total) {
    CHECK(total == 12);
    progress.push_back(done);
  };
  const auto run = runAtlas(
      axes, 5, 12,
      [&](std::size_t index, const AtlasCell& cell) {
        CHECK(progress.size() == seen.size());  // each cell is handed on before the next is computed
        CHECK(cell == (*page)[seen.size()]);
        seen.push_back(index);
        return true;
      },
      control);
  REQUIRE(run.ok());
  CHECK(*run == 12);
  CHECK(seen == std::vector<std::size_t>{5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
  CHECK(progress == std::vector<std::size_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});

  SECTION("a visitor that says stop ends the run there") {
    std::size_t calls = 0;
    const auto stopped = runAtlas(axes, 0, 100, [&](std::size_t, const AtlasCell&) { return ++calls < 3; });
    REQUIRE(stopped.ok());
    CHECK(*stopped == 3);
    CHECK(calls == 3);
  }
  SECTION("a cancel flag set during the run ends it Cancelled") {
    std::atomic<bool> cancel{false};
    std::size_t calls = 0;
    const auto cancelled = runAtlas(
        axes, 0, 100,
        [&](std::size_t, const AtlasCell&) {
          if (++calls == 2) cancel = true;
          return true;
        },
        RunControl{&cancel, {}});
    REQUIRE(!cancelled.ok());
    CHECK(cancelled.error().code == ErrorCode::Cancelled);
    CHECK(calls == 2);
  }
  SECTION("more cells than one run computes are refused before any is computed") {
    AtlasAxes big;
    big.coupler = std::vector<double>(64, 2.0);
    big.rocker = std::vector<double>(64, 2.0);
    big.frame = std::vector<double>(64, 2.0);
    REQUIRE(atlasCellCount(big) == 64u * 64u * 64u * 5u * 3u);
    std::size_t calls = 0;
    const auto refused =
        runAtlas(big, 0, atlasCellCount(big), [&](std::size_t, const AtlasCell&) { return ++calls > 0; });
    REQUIRE(!refused.ok());
    CHECK(calls == 0);
    CHECK(refused.error().field == "count");
    CHECK(refused.error().message == "an atlas run computes at most 100000 cells (asked 3932160)");
    // A page of it is fine: the grid is not capped, a run is.
    CHECK(runAtlas(big, 3932150, 100, [](std::size_t, const AtlasCell&) { return true; }).value() == 10);
  }
}
