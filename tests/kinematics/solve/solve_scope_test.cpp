// Tests kinematics/solve/solve_scope.h and the selection in a sweep (SolveRequest::only): what
// is solved for a selection, that the selected columns equal the full sweep's exactly, that the
// rest is neither computed nor stored, and that sweeping again into one result leaves nothing
// of the previous sweep behind.

#include "kinematics/solve/solve_scope.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;

namespace {

using Marks = std::vector<unsigned char>;

// Watt II: O2, O4, B, C (the base four-bar), P on the rocker, O6, and the dyad's joint E.
Mechanism wattII() { return makeSixBar(kWattIISixBar).value(); }

Selection links(std::vector<LinkId> ids) { return Selection{std::vector<PointId>{}, std::move(ids)}; }

}  // namespace

TEST_CASE("no selection solves and reports everything", "[sweep][scope]") {
  const Mechanism m = wattII();
  const SolveScope s = scopeOf(m, Selection{});
  CHECK(s.solvePoint == Marks(m.points.size(), 1));
  CHECK(s.reportPoint == Marks(m.points.size(), 1));
  CHECK(s.solveLink == Marks(m.links.size(), 1));
  CHECK(s.reportLink == Marks(m.links.size(), 1));
}

TEST_CASE("the solver's steps leave out the ground pivots, which a prepared pose holds", "[sweep][scope]") {
  const Mechanism m = wattII();  // O2, O4, B, C, P, O6, E: O2, O4 and O6 are ground pivots
  const SolveScope s = scopeOf(m, Selection{});
  std::vector<std::size_t> steps;
  for (const PointId p : s.pointSteps) steps.push_back(p.index);
  CHECK(steps == std::vector<std::size_t>{2, 3, 4, 6});
  Pose pose;
  preparePose(m, pose);
  for (const std::size_t i : {0, 1, 5})
    CHECK(pose.position[i] == std::get<GroundPoint>(m.points[i].definition).position);
  // So a scoped solve of a prepared pose places them all the same.
  REQUIRE(solvePoseInto(m, {0.3, 1.0, 0.0}, {}, pose, {}, &s).status == PoseStatus::Ok);
  const Pose whole = solvePose(m, {0.3, 1.0, 0.0}).value();
  for (std::size_t i = 0; i < m.points.size(); ++i) CHECK(pose.position[i] == whole.position[i]);
}

TEST_CASE("a six-bar's base rocker needs only the base four-bar", "[sweep][scope]") {
  const Mechanism m = wattII();
  REQUIRE(m.points.size() == 7);
  const SolveScope s = scopeOf(m, links({fourbar::kRocker}));
  CHECK(s.solvePoint == Marks{1, 1, 1, 1, 0, 0, 0});  // O2, O4, B, C; not P, O6, E
  CHECK(s.reportPoint == Marks(7, 0));
  Marks rockerOnly(m.links.size(), 0);
  rockerOnly[fourbar::kRocker.index] = 1;
  CHECK(s.solveLink == rockerOnly);
  CHECK(s.reportLink == rockerOnly);
}

TEST_CASE("a point on a link needs the link's angle, the last dyad needs everything", "[sweep][scope]") {
  const Mechanism m = wattII();
  const SolveScope p = scopeOf(m, Selection{std::vector<PointId>{PointId{4}}, std::vector<LinkId>{}});
  CHECK(p.solvePoint == Marks{1, 1, 1, 1, 1, 0, 0});
  CHECK(p.solveLink[fourbar::kRocker.index] == 1);  // P is fixed on the rocker
  CHECK(p.reportPoint == Marks{0, 0, 0, 0, 1, 0, 0});
  const SolveScope e = scopeOf(m, Selection{std::vector<PointId>{PointId{6}}, std::vector<LinkId>{}});
  CHECK(e.solvePoint == Marks(7, 1));
}

TEST_CASE("one free point of a Newton group needs its whole group", "[sweep][scope][newton]") {
  const Mechanism m = makeStephensonIINewton().value();
  const SolveScope s = scopeOf(m, links({stephenson2::kRocker}));
  CHECK(s.solvePoint == Marks(m.points.size(), 1));  // J4 is in the group J2, J3, J4, J6
  const SolveScope crank = scopeOf(m, links({stephenson2::kCrank}));
  Marks crankOnly(m.points.size(), 0);
  crankOnly[stephenson2::kJ0.index] = crankOnly[stephenson2::kJ1.index] = 1;
  CHECK(crank.solvePoint == crankOnly);
}

TEST_CASE("a selection naming an id the mechanism lacks is refused, naming the entry", "[sweep][scope][errors]") {
  const Mechanism m = wattII();
  const auto e = checkSelection(m, Selection{std::vector<PointId>{PointId{0}, PointId{7}}, std::nullopt});
  REQUIRE(e.has_value());
  CHECK(e->field == "only.points[1]");
  CHECK(e->message == "only.points[1] is point 7, but the mechanism has 7 points");
  SolveRequest request;
  request.only = links({LinkId{9}});
  const auto s = sweep(m, {0.0, 1.0, 3, 1.0, 0.0}, request);
  REQUIRE_FALSE(s.ok());
  CHECK(s.error().field == "only.links[0]");
}

TEST_CASE("selected columns equal the full sweep's exactly, the others are empty", "[sweep][scope]") {
  const Mechanism m = wattII();
  const SweepSpec spec{0.0, 2.0 * kPi, 721, 2.0 * kPi, 3.0};
  const auto full = sweep(m, spec);
  REQUIRE(full.ok());
  SolveRequest request;
  request.only = Selection{std::vector<PointId>{PointId{4}}, std::vector<LinkId>{fourbar::kRocker}};
  const auto part = sweep(m, spec, request);
  REQUIRE(part.ok());
  CHECK(part->report == full->report);
  const auto k = fourbar::kRocker.index;
  CHECK(part->linkAngle[k] == full->linkAngle[k]);
  CHECK(part->linkOmega[k] == full->linkOmega[k]);
  CHECK(part->linkAlpha[k] == full->linkAlpha[k]);
  CHECK(part->position[4] == full->position[4]);
  CHECK(part->acceleration[4] == full->acceleration[4]);
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (i == 4) continue;
    CHECK(part->position[i].empty());
    CHECK(part->velocity[i].empty());
    CHECK(part->transmissionAngle[i].empty());
  }
  for (std::size_t j = 0; j < m.links.size(); ++j)
    if (j != k) CHECK(part->linkAngle[j].empty());
}

TEST_CASE("without transmission angles the dyads' columns are empty, the rest unchanged", "[sweep][scope]") {
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  const SweepSpec spec{0.0, 2.0 * kPi, 361, 1.0, 0.0};
  SolveRequest request;
  request.transmissionAngles = false;
  const auto without = sweep(m, spec, request);
  const auto with = sweep(m, spec);
  REQUIRE(without.ok());
  REQUIRE(with.ok());
  CHECK(without->transmissionAngle[fourbar::kC.index].empty());
  CHECK(with->transmissionAngle[fourbar::kC.index].size() == 361);
  CHECK(without->linkAlpha == with->linkAlpha);
  CHECK(without->position == with->position);
}

TEST_CASE("sweeping again into one result leaves nothing of the previous sweep", "[sweep][scope]") {
  // A triple rocker (frame 50, crank 40, coupler 30, rocker 35: S + L > P + Q) cannot turn its
  // crank fully: its failed samples must read 0 although the result held a longer, fully
  // assembled sweep of another linkage before.
  const Mechanism turns = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  const Mechanism rocks = makeFourBar({50.0, 40.0, 30.0, 35.0}, Branch::Open).value();
  const SweepSpec big{0.0, 2.0 * kPi, 721, 2.0, 1.0};
  const SweepSpec small{0.0, 2.0 * kPi, 361, 3.0, 0.0};
  SweepResult reused;
  REQUIRE_FALSE(sweepInto(turns, big, SolveRequest{}, reused).has_value());
  REQUIRE_FALSE(sweepInto(rocks, small, SolveRequest{}, reused).has_value());
  const auto fresh = sweep(rocks, small);
  REQUIRE(fresh.ok());
  REQUIRE_FALSE(fresh->notAssembled.empty());
  CHECK(reused.report == fresh->report);
  CHECK(reused.position == fresh->position);
  CHECK(reused.velocity == fresh->velocity);
  CHECK(reused.acceleration == fresh->acceleration);
  CHECK(reused.linkAngle == fresh->linkAngle);
  CHECK(reused.linkOmega == fresh->linkOmega);
  CHECK(reused.linkAlpha == fresh->linkAlpha);
  CHECK(reused.transmissionAngle == fresh->transmissionAngle);
  CHECK(reused.notAssembled == fresh->notAssembled);
  CHECK(reused.singularAngles == fresh->singularAngles);
  CHECK(reused.firstFailure == fresh->firstFailure);
}

TEST_CASE("a refused sweepInto leaves the result as it was", "[sweep][scope][errors]") {
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  SweepResult out;
  REQUIRE_FALSE(sweepInto(m, {0.0, 1.0, 5, 1.0, 0.0}, SolveRequest{}, out).has_value());
  const SweepResult before = out;
  const auto e = sweepInto(m, {0.0, 1.0, 0, 1.0, 0.0}, SolveRequest{}, out);
  REQUIRE(e.has_value());
  CHECK(e->field == "samples");
  CHECK(out.position == before.position);
  CHECK(out.report == before.report);
}
