// Tests kinematics/design/fourbar_dimensions.h: a recognised four-bar's lengths, branch and
// coupler point are read and set the same way on makeFourBar's four-bar and on one drawn point
// by point (O4 first, C's parents (O4, B), the coupler link C→B, the frame at 30°, a crank
// phase). After an edit asFourBar reads back what was set, and the drawn four-bar solves to
// makeFourBar's positions with the same dimensions, turned and moved onto its frame line.

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/kinematics/design/drawn_fourbar.h"
#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <array>
#include <cmath>

using namespace linkwright::kinematics;
using namespace linkwright::test;

namespace {

// Crank-rockers (the crank turns fully), so every crank angle assembles.
constexpr FourBarLengths kThesisLengths{60, 25, 70, 45};
constexpr FourBarLengths kAlviLengths{80, 20, 66, 56};
constexpr FourBarLengths kMirandaLengths{250, 100, 225, 150};
constexpr CouplerPointSpec kP{35, 20};

FourBarStructure fourBarOf(const Mechanism& m) {
  const auto s = asFourBar(m);
  REQUIRE(s.has_value());
  return *s;
}

Pose poseAt(const Mechanism& m, double inputAngle) {
  const auto pose = solvePose(m, {inputAngle, 0.0, 0.0}, {false, false});
  INFO((pose.ok() ? std::string() : pose.error().message));
  REQUIRE(pose.ok());
  return *pose;
}

// The drawn four-bar `drawn` (laid out as `d`, dimensions edited) against makeFourBar with
// the same dimensions, at crank angles all round the frame line: each of O2, O4, B, C (and P)
// sits where makeFourBar's does, turned by the frame angle and moved to O2. The tolerance is
// 1e-12 of the linkage's size (a few roundings of the angle and of each dyad).
void checkSolvesLikeMakeFourBar(const DrawnFourBar& d, const Mechanism& drawn, const FourBarLengths& lengths,
                                Branch branch, std::optional<CouplerPointSpec> spec) {
  const Mechanism reference = makeFourBar(lengths, branch, "mm", spec).value();
  const FourBarStructure s = fourBarOf(drawn);
  Eigen::Matrix2d turn;
  turn << std::cos(d.frameAngle), -std::sin(d.frameAngle), std::sin(d.frameAngle), std::cos(d.frameAngle);
  const double tolerance = 1e-12 * (d.origin.norm() + lengths.frame + lengths.crank + lengths.coupler + lengths.rocker);
  std::vector<std::array<PointId, 2>> pairs{
      {kDrawnO2, fourbar::kO2}, {kDrawnO4, fourbar::kO4}, {kDrawnB, fourbar::kB}, {kDrawnC, fourbar::kC}};
  if (spec) pairs.push_back({kDrawnP, fourbar::kCouplerPoint});
  REQUIRE(drawn.points.size() == pairs.size());
  for (const double crankDeg : {0.0, 37.0, 90.0, 151.0, 180.0, 245.0, 300.0}) {
    const Pose expected = poseAt(reference, degToRad(crankDeg));
    const Pose actual = poseAt(drawn, s.inputAngle(degToRad(crankDeg)));
    for (const auto& [mine, theirs] : pairs) {
      std::string why;
      const Eigen::Vector2d moved = d.origin + Eigen::Vector2d(turn * expected.position[theirs.index]);
      const bool close = near(actual.position[mine.index], moved, tolerance, &why);
      CAPTURE(crankDeg, drawn.points[mine.index].name, why);
      CHECK(close);
    }
  }
}

}  // namespace

TEST_CASE("couplerPointOf reads P along B→C whichever way the coupler link runs", "[design][fourbar]") {
  const Mechanism made = makeFourBar(kThesisLengths, Branch::Open, "mm", CouplerPointSpec{35, -20.25}).value();
  const auto p = couplerPointOf(made, fourBarOf(made));
  REQUIRE(p.has_value());
  CHECK(p->id == fourbar::kCouplerPoint);
  CHECK(p->spec == CouplerPointSpec{35, -20.25});

  const DrawnFourBar d = drawnFourBar(kThesisLengths, Branch::Open, CouplerPointSpec{35, -20.25});
  const auto q = couplerPointOf(d.mechanism, fourBarOf(d.mechanism));
  REQUIRE(q.has_value());
  CHECK(q->id == kDrawnP);
  CHECK(q->spec == CouplerPointSpec{35, -20.25});

  CHECK_FALSE(
      couplerPointOf(*makeFourBar(kThesisLengths, Branch::Open), fourBarOf(*makeFourBar(kThesisLengths, Branch::Open)))
          .has_value());
  const Mechanism bare = drawnFourBar(kThesisLengths, Branch::Open).mechanism;
  CHECK_FALSE(couplerPointOf(bare, fourBarOf(bare)).has_value());
}

TEST_CASE("the drawn four-bar solves as makeFourBar's, turned onto its frame line", "[design][fourbar]") {
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const DrawnFourBar d = drawnFourBar(kThesisLengths, branch, kP);
    const FourBarStructure s = fourBarOf(d.mechanism);
    CHECK(s.branch == branch);
    CHECK(s.frameAngle == within(d.frameAngle, 1e-15));
    CHECK(s.crankPhase == d.crankPhase);
    checkSolvesLikeMakeFourBar(d, d.mechanism, kThesisLengths, branch, kP);
  }
}

TEST_CASE("withFourBarLengths sets the four lengths and keeps the rest", "[design][fourbar]") {
  for (const Branch branch : {Branch::Open, Branch::Crossed})
    for (const FourBarLengths& lengths : {kAlviLengths, kMirandaLengths}) {
      CAPTURE(branch == Branch::Open, lengths.frame);
      // makeFourBar's four-bar becomes exactly the one makeFourBar builds with the new lengths.
      const Mechanism made = makeFourBar(kThesisLengths, branch, "mm", kP).value();
      const Mechanism madeEdited = withFourBarLengths(made, fourBarOf(made), lengths);
      CHECK(madeEdited == makeFourBar(lengths, branch, "mm", kP).value());
      CHECK(fourBarOf(madeEdited).lengths == lengths);

      const DrawnFourBar d = drawnFourBar(kThesisLengths, branch, kP);
      const Mechanism edited = withFourBarLengths(d.mechanism, fourBarOf(d.mechanism), lengths);
      const FourBarStructure s = fourBarOf(edited);
      CHECK(s.lengths.crank == lengths.crank);
      CHECK(s.lengths.coupler == lengths.coupler);
      CHECK(s.lengths.rocker == lengths.rocker);
      // O4 is placed at frame · (cos 30°, sin 30°) from O2 and the frame read back as the
      // distance: one rounding of each.
      CHECK(s.lengths.frame == within(lengths.frame, 1e-15 * lengths.frame));
      CHECK(s.branch == branch);
      CHECK(s.frameAngle == within(d.frameAngle, 1e-15));
      CHECK(s.crankPhase == d.crankPhase);
      CHECK(s.o2 == kDrawnO2);
      CHECK(std::get<GroundPoint>(edited.points[kDrawnO2.index].definition).position == d.origin);
      // P keeps its place relative to B (along B→C), though its link runs C→B.
      CHECK(couplerPointOf(edited, s)->spec == kP);
      checkSolvesLikeMakeFourBar(d, edited, lengths, branch, kP);
    }
}

TEST_CASE("withFourBarBranch sets the four-bar's branch whichever way C's parents run", "[design][fourbar]") {
  for (const Branch from : {Branch::Open, Branch::Crossed})
    for (const Branch to : {Branch::Open, Branch::Crossed}) {
      CAPTURE(from == Branch::Open, to == Branch::Open);
      const Mechanism made = makeFourBar(kThesisLengths, from, "mm", kP).value();
      const Mechanism madeEdited = withFourBarBranch(made, fourBarOf(made), to);
      CHECK(madeEdited == makeFourBar(kThesisLengths, to, "mm", kP).value());
      CHECK(fourBarOf(madeEdited).branch == to);

      const DrawnFourBar d = drawnFourBar(kThesisLengths, from, kP);
      const Mechanism edited = withFourBarBranch(d.mechanism, fourBarOf(d.mechanism), to);
      CHECK(fourBarOf(edited).branch == to);
      CHECK(fourBarOf(edited).lengths == fourBarOf(d.mechanism).lengths);
      CHECK(edited == drawnFourBar(kThesisLengths, to, kP).mechanism);
      checkSolvesLikeMakeFourBar(d, edited, kThesisLengths, to, kP);
    }
}

TEST_CASE("withCouplerPoint adds, moves and removes P", "[design][fourbar]") {
  const CouplerPointSpec moved{-10, 12.5};
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    CAPTURE(branch == Branch::Open);
    // makeFourBar's: each edit gives exactly what makeFourBar builds with that P.
    const Mechanism bare = makeFourBar(kThesisLengths, branch).value();
    const auto added = withCouplerPoint(bare, fourBarOf(bare), kP);
    REQUIRE(added.ok());
    CHECK(*added == makeFourBar(kThesisLengths, branch, "mm", kP).value());
    const auto movedP = withCouplerPoint(*added, fourBarOf(*added), moved);
    REQUIRE(movedP.ok());
    CHECK(*movedP == makeFourBar(kThesisLengths, branch, "mm", moved).value());
    const auto removed = withCouplerPoint(*movedP, fourBarOf(*movedP), std::nullopt);
    REQUIRE(removed.ok());
    CHECK(*removed == bare);
    CHECK(*withCouplerPoint(bare, fourBarOf(bare), std::nullopt) == bare);

    // The drawn one: P on the link C→B, offsets restated along B→C.
    const DrawnFourBar d = drawnFourBar(kThesisLengths, branch);
    const auto drawnAdded = withCouplerPoint(d.mechanism, fourBarOf(d.mechanism), kP);
    REQUIRE(drawnAdded.ok());
    CHECK(drawnAdded->points.back().name == "P");
    CHECK(couplerPointOf(*drawnAdded, fourBarOf(*drawnAdded))->spec == kP);
    CHECK(*drawnAdded == drawnFourBar(kThesisLengths, branch, kP).mechanism);
    checkSolvesLikeMakeFourBar(d, *drawnAdded, kThesisLengths, branch, kP);
    const auto drawnMoved = withCouplerPoint(*drawnAdded, fourBarOf(*drawnAdded), moved);
    REQUIRE(drawnMoved.ok());
    CHECK(couplerPointOf(*drawnMoved, fourBarOf(*drawnMoved))->spec == moved);
    checkSolvesLikeMakeFourBar(d, *drawnMoved, kThesisLengths, branch, moved);
    const auto drawnRemoved = withCouplerPoint(*drawnMoved, fourBarOf(*drawnMoved), std::nullopt);
    REQUIRE(drawnRemoved.ok());
    CHECK(*drawnRemoved == d.mechanism);
  }
}

TEST_CASE("withCouplerPoint refuses a four-bar with no coupler link", "[design][fourbar][errors]") {
  Mechanism m = makeFourBar(kThesisLengths, Branch::Open).value();
  m.links.erase(m.links.begin() + static_cast<std::ptrdiff_t>(fourbar::kCoupler.index));
  const auto p = withCouplerPoint(m, fourBarOf(m), kP);
  REQUIRE_FALSE(p.ok());
  CHECK(p.error().code == ErrorCode::InvalidStructure);
  CHECK(p.error().field == "couplerPoint");
}

TEST_CASE("every dimension edited in turn on the drawn four-bar", "[design][fourbar]") {
  const DrawnFourBar d = drawnFourBar(kThesisLengths, Branch::Open);
  Mechanism m = withFourBarLengths(d.mechanism, fourBarOf(d.mechanism), kMirandaLengths);
  m = withFourBarBranch(m, fourBarOf(m), Branch::Crossed);
  m = withCouplerPoint(m, fourBarOf(m), CouplerPointSpec{112.5, 0}).value();
  m = withFourBarLengths(m, fourBarOf(m), kAlviLengths);
  const FourBarStructure s = fourBarOf(m);
  CHECK(s.lengths.crank == kAlviLengths.crank);
  CHECK(s.lengths.coupler == kAlviLengths.coupler);
  CHECK(s.lengths.rocker == kAlviLengths.rocker);
  CHECK(s.lengths.frame == within(kAlviLengths.frame, 1e-15 * kAlviLengths.frame));
  CHECK(s.branch == Branch::Crossed);
  CHECK(couplerPointOf(m, s)->spec == CouplerPointSpec{112.5, 0});
  checkSolvesLikeMakeFourBar(d, m, kAlviLengths, Branch::Crossed, CouplerPointSpec{112.5, 0});
}
