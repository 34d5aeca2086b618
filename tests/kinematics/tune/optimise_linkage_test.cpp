// Tests kinematics/tune/optimise_linkage.h: for each objective, on the thesis crank-rocker,
// the funsho four-bar with its masses and the LS3 slider-crank, the returned design's objective,
// recomputed here from the design alone by the ordinary sweep (not the optimiser's own value),
// beats the start's; no defect is added (the Grashof class and the branch kept, every dimension
// in its range, the fixed pivots where they were, the design moving through its whole grid);
// the design really changed, and the candidates measured were different designs; a seed repeats
// the result to the last bit; a cancel returns a valid best so far; bad requests are refused
// naming the field.

#include "kinematics/tune/optimise_linkage.h"

#include "kinematics/analysis/transmission.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <set>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;

namespace {

Design example(const std::string& name) {
  auto d = designForExample(name);
  REQUIRE(d.has_value());
  return *d;
}

// The thesis crank-rocker with a coupler point P 35 mm along and 20 mm across B→C.
Design thesisWithP() {
  auto d = fourBarDesign(kThesis, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0});
  REQUIRE(d.ok());
  return *d;
}

SweepResult sweepOf(const Design& d) {
  auto s = sweep(d.mechanism, designSweepSpec(d));
  REQUIRE(s.ok());
  return std::move(s).value();
}

// Peak |α| of `link` over the samples where rates exist, from the ordinary sweep of the
// design's range 1000 times as fine as its grid: within 1e-10 of the exact peak.
double peakAlpha(const Design& d, const std::string& link) {
  SweepSpec fine = designSweepSpec(d);
  fine.samples = 1000 * (fine.samples - 1) + 1;
  auto swept = sweep(d.mechanism, fine);
  REQUIRE(swept.ok());
  const SweepResult& s = *swept;
  const std::size_t l = d.mechanism.findLink(link)->index;
  double peak = 0.0;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.ok(j)) peak = std::max(peak, std::abs(s.linkAlpha[l][j]));
  return peak;
}

// The exact worst min(μ, π − μ) of a four-bar whose crank turns fully.
double worstTransmission(const Design& d) {
  const auto f = asFourBar(d.mechanism);
  REQUIRE(f.has_value());
  const auto worst = worstTransmissionBetween(f->lengths, 0.0, 2.0 * kPi);
  REQUIRE(worst.has_value());
  return *worst;
}

// The worst distance of the targets from P's path, the path solved by the pose solver every
// 0.002° (a second method: the nearest of dense points, not the optimiser's search between its
// grid's samples; within 1e-6 mm of the path's for targets 0.1 mm or more away).
double worstPathDistance(const Design& d, const std::vector<Eigen::Vector2d>& targets) {
  const std::size_t p = d.mechanism.findPoint("P")->index;
  std::vector<Eigen::Vector2d> path;
  for (int i = 0; i < 180000; ++i) {
    const auto pose = solvePose(d.mechanism, {degToRad(0.002 * i), 0.0, 0.0});
    REQUIRE(pose.ok());
    path.push_back(pose->position[p]);
  }
  double worst = 0.0;
  for (const Eigen::Vector2d& t : targets) {
    double nearest = 1e300;
    for (const Eigen::Vector2d& q : path) nearest = std::min(nearest, (q - t).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The RMS driving torque over one turn from the forces of the ordinary sweep, by the
// trapezoidal rule.
double rmsTorque(const Design& d) {
  const SweepSpec turn = designTurn(d);
  auto s = sweep(d.mechanism, turn);
  REQUIRE(s.ok());
  const auto forces = sweepForces(d.mechanism, d.dynamics, *s);
  REQUIRE(forces.ok());
  const std::vector<double>& t = forces->driveTorque;
  double integral = 0.0;
  for (std::size_t j = 1; j < t.size(); ++j) integral += 0.5 * (t[j - 1] * t[j - 1] + t[j] * t[j]);
  return std::sqrt(integral / static_cast<double>(t.size() - 1));
}

// No defect added: the class and branch kept, the ranges and the fixed pivots respected, the
// whole grid assembled without a lock; and the design really moved.
void checkKept(const Design& start, const LinkageOptimisation& r) {
  CHECK(r.improved);
  CHECK(r.constraints.assembles);
  CHECK(r.constraints.branchKept);
  CHECK(r.constraints.withinRanges);
  CHECK(r.constraints.pivotsKept);
  if (const auto before = asFourBar(start.mechanism)) {
    const auto after = asFourBar(r.design.mechanism);
    REQUIRE(after.has_value());
    CHECK(classifyGrashof(after->lengths).category == classifyGrashof(before->lengths).category);
    CHECK(after->branch == before->branch);
  }
  const SweepResult s = sweepOf(r.design);
  for (std::size_t j = 0; j < s.size(); ++j) REQUIRE(s.assembled(j));
  CHECK(s.lockedBetween.empty());
  const auto dims = toleranceDimensions(r.design.mechanism);
  REQUIRE(dims.size() == r.dimensions.size());
  double moved = 0.0;
  for (std::size_t i = 0; i < dims.size(); ++i) {
    CAPTURE(dims[i].name);
    const OptimiseDimension& d = r.dimensions[i];
    CHECK(dims[i].value >= d.lo - 1e-9);
    CHECK(dims[i].value <= d.hi + 1e-9);
    if (d.fixed) CHECK(r.values[i] == d.dimension.value);
    moved = std::max(moved, std::abs(r.values[i] - d.dimension.value));
  }
  for (std::size_t p = 0; p < start.mechanism.points.size(); ++p)
    if (std::holds_alternative<GroundPoint>(start.mechanism.points[p].definition))
      CHECK(start.mechanism.points[p] == r.design.mechanism.points[p]);
  // An optimiser that measured the start again and again would return it unchanged.
  CHECK(moved > 0.1);
  CHECK_FALSE(r.design == start);
  std::set<std::vector<double>> distinct(r.evaluated.begin(), r.evaluated.end());
  CHECK(distinct.size() > 20);
}

OptimiseRequest requestFor(OptimiseObjective objective, int evaluations = 300) {
  OptimiseRequest request;
  request.objective = std::move(objective);
  request.options.evaluations = evaluations;
  request.options.starts = 2;
  request.options.recordEvaluations = true;
  return request;
}

}  // namespace

TEST_CASE("optimising the rocker's peak alpha of the thesis crank-rocker lowers it, measured afresh", "[optimise]") {
  const Design start = example("thesis-crank-rocker");
  const auto r = optimiseLinkage(start, requestFor({ObjectiveKind::PeakAlpha, "rocker"}));
  REQUIRE(r.ok());
  const double before = peakAlpha(start, "rocker"), after = peakAlpha(r->design, "rocker");
  CHECK(r->before == Approx(before).epsilon(1e-9));
  CHECK(r->after == Approx(after).epsilon(1e-9));
  CHECK(after < 0.9 * before);
  checkKept(start, *r);
  CHECK(r->curveBefore.x.size() == start.samples);
  CHECK(r->curveAfter.y.size() == start.samples);
}

TEST_CASE("optimising the worst transmission angle raises the exact worst over the turn", "[optimise]") {
  const Design start = example("thesis-crank-rocker");
  const auto r = optimiseLinkage(start, requestFor({ObjectiveKind::Transmission}));
  REQUIRE(r.ok());
  const double before = worstTransmission(start), after = worstTransmission(r->design);
  CHECK(r->before == Approx(before).epsilon(1e-12));
  CHECK(r->after == Approx(after).epsilon(1e-12));
  CHECK(radToDeg(after) > radToDeg(before) + 5.0);
  checkKept(start, *r);
}

TEST_CASE("optimising a coupler point's path brings it to targets from another coupler curve", "[optimise]") {
  const Design start = thesisWithP();
  // Targets on the curve of the coupler point 40 mm along and 28 mm across: P may move there.
  auto other = fourBarDesign(kThesis, Branch::Open, "mm", CouplerPointSpec{40.0, 28.0});
  REQUIRE(other.ok());
  std::vector<Eigen::Vector2d> targets;
  for (const double deg : {0.0, 60.0, 120.0, 180.0, 240.0, 300.0}) {
    const auto pose = solvePose(other->mechanism, {degToRad(deg), 0.0, 0.0});
    REQUIRE(pose.ok());
    targets.push_back(pose->position[other->mechanism.findPoint("P")->index]);
  }
  OptimiseObjective objective{ObjectiveKind::Path};
  objective.targets = targets;
  const auto r = optimiseLinkage(start, requestFor(objective, 400));
  REQUIRE(r.ok());
  const double before = worstPathDistance(start, targets), after = worstPathDistance(r->design, targets);
  CHECK(r->before == Approx(before).margin(1e-5));  // the path's distance, not its grid's chords
  CHECK(after < 0.25 * before);
  checkKept(start, *r);

  SECTION("the RMS measure is the root mean square of the same distances") {
    objective.measure = PathMeasure::Rms;
    const auto rms = optimiseLinkage(start, requestFor(objective, 10));
    REQUIRE(rms.ok());
    CHECK(rms->before <= r->before);
    CHECK(rms->before > 0.3 * r->before);
  }
}

TEST_CASE("optimising the RMS driving torque of the funsho four-bar with its masses lowers it", "[optimise]") {
  const Design start = example("funsho-fourbar");
  const auto r = optimiseLinkage(start, requestFor({ObjectiveKind::RmsTorque}, 200));
  REQUIRE(r.ok());
  const double before = rmsTorque(start), after = rmsTorque(r->design);
  CHECK(r->before == Approx(before).epsilon(1e-9));
  CHECK(r->after == Approx(after).epsilon(1e-9));
  CHECK(after < 0.9 * before);
  checkKept(start, *r);
}

TEST_CASE("optimising the LS3 slider-crank's rod alpha keeps the crank pivot and lowers the peak", "[optimise]") {
  const Design start = example("ls3-engine");
  const auto r = optimiseLinkage(start, requestFor({ObjectiveKind::PeakAlpha, "rod"}, 200));
  REQUIRE(r.ok());
  CHECK(peakAlpha(r->design, "rod") < 0.95 * peakAlpha(start, "rod"));
  checkKept(start, *r);
}

TEST_CASE("an optimisation repeats to the last bit for a seed", "[optimise]") {
  const Design start = example("thesis-crank-rocker");
  OptimiseRequest request = requestFor({ObjectiveKind::PeakAlpha, "rocker"}, 200);
  request.options.starts = 3;
  const auto a = optimiseLinkage(start, request);
  const auto b = optimiseLinkage(start, request);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a->design == b->design);
  CHECK(a->values == b->values);
  CHECK(a->evaluated == b->evaluated);
  CHECK(std::memcmp(&a->after, &b->after, sizeof(double)) == 0);
  request.options.seed = 7;
  const auto c = optimiseLinkage(start, request);
  REQUIRE(c.ok());
  CHECK(c->improved);  // another seed may find another design, as good a one
  CHECK(c->constraints.assembles);
}

TEST_CASE("a cancelled optimisation returns the best design found before", "[optimise]") {
  const Design start = example("thesis-crank-rocker");
  std::atomic<bool> cancel{false};
  int calls = 0;
  const auto r =
      optimiseLinkage(start, requestFor({ObjectiveKind::PeakAlpha, "rocker"}, 1000), &cancel, [&](int done, int total) {
        ++calls;
        CHECK(total == 1000);
        if (done == 30) cancel = true;
      });
  REQUIRE(r.ok());
  CHECK(r->cancelled);
  CHECK(r->evaluations == 30);
  CHECK(calls == 30);
  CHECK(r->constraints.assembles);
  CHECK(r->after <= r->before);
  CHECK(r->after == Approx(peakAlpha(r->design, "rocker")).epsilon(1e-9));
}

TEST_CASE("bad optimisation requests are refused naming the field", "[optimise]") {
  const Design thesis = example("thesis-crank-rocker");
  const auto refusal = [](const Design& d, const OptimiseRequest& request) {
    const auto r = optimiseLinkage(d, request);
    REQUIRE_FALSE(r.ok());
    return r.error();
  };
  auto e = refusal(thesis, requestFor({ObjectiveKind::PeakAlpha, "boom"}));
  CHECK(e.field == "objective.link");
  CHECK(e.message == "objective.link: the linkage has no link named 'boom' (its links: crank, coupler, rocker)");

  e = refusal(thesis, requestFor({ObjectiveKind::PeakAlpha, "crank"}));
  CHECK(e.field == "objective.link");
  CHECK(e.message.find("the same at every sample") != std::string::npos);

  e = refusal(thesisWithP(), requestFor({ObjectiveKind::Path}));
  CHECK(e.field == "objective.targets");
  CHECK(e.message == "objective.targets: the target path is empty (give at least one point)");

  e = refusal(thesis, requestFor({ObjectiveKind::RmsTorque}));
  CHECK(e.field == "dynamics");
  CHECK(e.message.find("needs the links' masses") != std::string::npos);

  OptimiseRequest request = requestFor({ObjectiveKind::Transmission});
  request.constraints.ranges = {{"crank length", 30.0, 20.0}};
  e = refusal(thesis, request);
  CHECK(e.field == "ranges[0]");
  CHECK(e.message == "ranges[0] (crank length) must run from a finite lo to a finite hi ≥ lo (got 30 to 20)");

  request.constraints.ranges = {{"crank length", 26.0, 30.0}};
  e = refusal(thesis, request);
  CHECK(e.message == "ranges[0] (crank length) must hold the start, 25 (got 26 to 30)");

  request.constraints.ranges = {{"wheel length", 1.0, 2.0}};
  CHECK(refusal(thesis, request).field == "ranges[0].name");

  request.constraints.ranges = {};
  request.constraints.fixedPivots = std::vector<std::string>{"O2", "B"};
  e = refusal(thesis, request);
  CHECK(e.field == "fixedPivots[1]");
  CHECK(e.message == "fixedPivots[1]: 'B' is not a ground pivot of the linkage");

  request.constraints.fixedPivots.reset();
  request.constraints.lengthRange = 0.0;
  CHECK(refusal(thesis, request).field == "lengthRange");

  request.constraints.lengthRange = 0.5;
  request.options.evaluations = 5;
  e = refusal(thesis, request);
  CHECK(e.message == "evaluations must be between 10 and 1000000 (got 5)");
}

TEST_CASE("a freed pivot is optimised, and the crank pivot alone stays fixed", "[optimise]") {
  const Design start = example("thesis-crank-rocker");
  OptimiseRequest request = requestFor({ObjectiveKind::Transmission}, 200);
  request.constraints.fixedPivots = std::vector<std::string>{"O2"};
  const auto r = optimiseLinkage(start, request);
  REQUIRE(r.ok());
  const auto frame = std::find_if(r->dimensions.begin(), r->dimensions.end(),
                                  [](const OptimiseDimension& d) { return d.dimension.name == "frame length"; });
  REQUIRE(frame != r->dimensions.end());
  CHECK_FALSE(frame->fixed);
  CHECK(frame->lo == Approx(30.0));
  CHECK(frame->hi == Approx(90.0));
  CHECK(start.mechanism.points[0] == r->design.mechanism.points[0]);
  CHECK(worstTransmission(r->design) > worstTransmission(start));
}

// The objective is the design's, not its grid's: peak |α| and a six-bar's worst transmission
// angle refined between the 361 samples agree with a sweep 1000 times as fine to 1e-9
// relative (whose own sampling error there is below 1e-10), where the grid's samples alone are
// 1e-5 to 1e-4 off.
TEST_CASE("the objective's peak alpha and a six-bar's worst transmission are exact, not the grid's", "[optimise]") {
  auto [name, kind, link] = GENERATE(table<std::string, ObjectiveKind, std::string>({
      {"thesis-crank-rocker", ObjectiveKind::PeakAlpha, "rocker"},
      {"watt-ii", ObjectiveKind::PeakAlpha, "link6"},
      {"stephenson-ii", ObjectiveKind::PeakAlpha, "coupler"},
      {"stephenson-i", ObjectiveKind::Transmission, ""},
      {"shaper", ObjectiveKind::Transmission, ""},
  }));
  CAPTURE(name, link);
  const Design d = example(name);
  const OptimiseObjective objective{kind, link};
  REQUIRE_FALSE(checkObjective(d, objective));
  const auto measured = measureObjective(d, objective, sweepOf(d));
  REQUIRE(measured.has_value());
  SweepSpec fine = designSweepSpec(d);
  fine.samples = 1000 * (fine.samples - 1) + 1;
  const auto dense = sweep(d.mechanism, fine);
  REQUIRE(dense.ok());
  const auto denseValue = measureObjective(d, objective, *dense);
  REQUIRE(denseValue.has_value());
  // The dense sweep's samples alone, without refinement (the second method).
  double sampled = kind == ObjectiveKind::PeakAlpha ? 0.0 : kPi;
  for (std::size_t j = 0; j < dense->size(); ++j) {
    if (kind == ObjectiveKind::PeakAlpha) {
      if (dense->ok(j)) sampled = std::max(sampled, std::abs(dense->linkAlpha[d.mechanism.findLink(link)->index][j]));
      continue;
    }
    for (std::size_t p = 0; p < d.mechanism.points.size(); ++p)
      if (hasTransmissionAngle(d.mechanism.points[p].definition)) {
        const double mu = dense->transmissionAngle[p][j];
        sampled = std::min(sampled, std::min(mu, kPi - mu));
      }
  }
  CHECK(std::abs(measured->value - sampled) <= 1e-9 * std::abs(sampled));
  CHECK(std::abs(denseValue->value - measured->value) <= 1e-9 * std::abs(sampled));
}
