// Inversions checked by motion, not by naming alone: each inversion's mechanism is swept over
// a whole turn of its driver, and the driver turns fully (every sample assembles, no lock)
// exactly when its Grashof class (or the slider-crank's closed form) says so. The classes
// follow the textbook table (Norton Table 2-4): a Grashof chain gives two crank-rockers, a
// double-crank and a double-rocker; a non-Grashof chain four triple-rockers; a change-point
// chain four change points.

#include "kinematics/analysis/inversions.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <array>
#include <cmath>

using namespace linkwright::kinematics;

namespace {

// A whole turn of the driver in 0.5° steps: fine enough that a lock (the shortest non-full
// range below is tens of degrees) cannot fall between two samples unnoticed, since the sweep
// reports locks between samples too.
SweepResult turn(const Mechanism& m) {
  const auto result = sweep(m, {0.0, 2.0 * kPi, 721, 1.0, 0.0});
  REQUIRE(result);
  return *result;
}

bool turnsFully(const SweepResult& s) { return s.notAssembled.empty() && s.lockedBetween.empty(); }

double lengthOf(const FourBarLengths& l, LinkRole role) {
  switch (role) {
  case LinkRole::Frame: return l.frame;
  case LinkRole::Crank: return l.crank;
  case LinkRole::Coupler: return l.coupler;
  case LinkRole::Rocker: return l.rocker;
  }
  return 0.0;
}

bool adjacent(LinkRole a, LinkRole b) {
  const int d = std::abs(static_cast<int>(a) - static_cast<int>(b));
  return d == 1 || d == 3;
}

void checkInversions(const FourBarLengths& original, const std::array<GrashofClass, 4>& expected) {
  const auto inversions = fourBarInversions(original);
  REQUIRE(inversions);
  REQUIRE(inversions->size() == 4);
  for (std::size_t g = 0; g < 4; ++g) {
    const FourBarInversion& inv = (*inversions)[g];
    CAPTURE(g, inv.name);
    CHECK(inv.grounded == static_cast<LinkRole>(g));
    CHECK(adjacent(inv.grounded, inv.driven));
    CHECK(inv.lengths.frame == lengthOf(original, inv.grounded));
    CHECK(inv.lengths.crank == lengthOf(original, inv.driven));
    CHECK(inv.grashof.category == expected[g]);
    CHECK(inv.name == textbookName(expected[g]));
    CHECK(fourBarInputRange(inv.lengths).fullRotation == inv.grashof.inputFullyRotates);
    CHECK(turnsFully(turn(inv.mechanism)) == inv.grashof.inputFullyRotates);
  }
}

}  // namespace

TEST_CASE("a Grashof chain: two crank-rockers, a drag link and a double-rocker", "[inversions]") {
  // S = 2 (the crank), L = 7: 9 < 5 + 6. Ground the frame or the coupler (next to the crank),
  // the crank itself, or the rocker (opposite it).
  checkInversions({7.0, 2.0, 5.0, 6.0}, {GrashofClass::CrankRocker, GrashofClass::DoubleCrank,
                                         GrashofClass::CrankRocker, GrashofClass::DoubleRocker});
  // The thesis crank-rocker: its inversions by the same rule.
  checkInversions(kThesisCrankRocker, {GrashofClass::CrankRocker, GrashofClass::DoubleCrank, GrashofClass::CrankRocker,
                                       GrashofClass::DoubleRocker});
  // The shortest as the coupler: grounding the frame gives the double-rocker.
  checkInversions({7.0, 5.0, 2.0, 6.0}, {GrashofClass::DoubleRocker, GrashofClass::CrankRocker,
                                         GrashofClass::DoubleCrank, GrashofClass::CrankRocker});
}

TEST_CASE("a non-Grashof chain: four triple-rockers", "[inversions]") {
  // S + L = 2 + 8 > 5 + 4: no link turns fully relative to another.
  const auto t = GrashofClass::TripleRocker;
  checkInversions({8.0, 2.0, 5.0, 4.0}, {t, t, t, t});
  checkInversions({5.0, 4.0, 4.5, 4.2}, {t, t, t, t});
}

TEST_CASE("a change-point chain: four change points", "[inversions]") {
  const auto c = GrashofClass::ChangePoint;
  checkInversions({5.0, 2.0, 4.0, 3.0}, {c, c, c, c});  // 2 + 5 = 4 + 3
  checkInversions({5.0, 3.0, 5.0, 3.0}, {c, c, c, c});  // a parallelogram
}

TEST_CASE("inversions refuse bad lengths, naming the link", "[inversions]") {
  const auto r = fourBarInversions({60.0, -1.0, 70.0, 45.0});
  REQUIRE_FALSE(r);
  CHECK(r.error().field == "crank");
}

namespace {

// The output's net turn over one turn of the driver: 2π if it turns fully, about 0 if it rocks.
double outputTurn(const SweepResult& s, std::size_t link) {
  return std::abs(s.linkAngle[link].back() - s.linkAngle[link].front());
}

void checkSliderCrank(const SliderCrankInversion& inv) {
  CAPTURE(inv.name);
  REQUIRE(inv.mechanism);
  const SweepResult s = turn(*inv.mechanism);
  CHECK(turnsFully(s) == inv.driverTurnsFully);
  if (inv.grounded == SliderCrankLink::Crank || inv.grounded == SliderCrankLink::Rod) {
    REQUIRE(turnsFully(s));
    CHECK(std::abs(outputTurn(s, 1) - (inv.outputTurnsFully ? 2.0 * kPi : 0.0)) <= 1e-9);
  }
}

}  // namespace

TEST_CASE("the LS3 engine's inversions: engine, Whitworth, oscillating cylinder, pump", "[inversions]") {
  const auto r = sliderCrankInversions(kLs3Engine);
  REQUIRE(r);
  REQUIRE(r->size() == 4);
  const auto& v = *r;
  CHECK(v[0].name == "slider-crank");
  CHECK(v[1].name == "Whitworth quick return (rotating guide)");
  CHECK(v[2].name == "oscillating cylinder");
  CHECK(v[3].name == "fixed piston (pendulum pump)");
  CHECK(v[0].driverTurnsFully);
  CHECK(v[1].outputTurnsFully);
  CHECK_FALSE(v[2].outputTurnsFully);
  CHECK_FALSE(v[3].driverTurnsFully);
  for (const auto& inv : v) checkSliderCrank(inv);
}

TEST_CASE("a crank longer than its rod: crank-shaper, rotating cylinder, a pump whose rod turns", "[inversions]") {
  const auto r = sliderCrankInversions({60.0, 40.0, 0.0, false});
  REQUIRE(r);
  const auto& v = *r;
  CHECK_FALSE(v[0].driverTurnsFully);
  CHECK(v[1].name == "crank-shaper (oscillating guide)");
  CHECK(v[2].name == "rotating cylinder");
  CHECK(v[3].driverTurnsFully);
  for (const auto& inv : v) checkSliderCrank(inv);
}

TEST_CASE("an offset slider-crank: the slotted inversions are named, not built", "[inversions]") {
  const auto r = sliderCrankInversions({46.0, 150.0, 12.0, false});
  REQUIRE(r);
  const auto& v = *r;
  CHECK_FALSE(v[1].mechanism);
  CHECK_FALSE(v[2].mechanism);
  CHECK(v[1].note.find("offset 12") != std::string::npos);
  checkSliderCrank(v[0]);
  checkSliderCrank(v[3]);
  const auto bad = sliderCrankInversions({46.0, 0.0, 0.0, false});
  REQUIRE_FALSE(bad);
  CHECK(bad.error().field == "rod");
}

TEST_CASE("a slider-crank's dimensions read back from its points, offset and reversed", "[inversions]") {
  for (const SliderCrankGeometry g :
       {SliderCrankGeometry{46.0, 150.0, 12.0, false}, SliderCrankGeometry{46.0, 150.0, -20.0, false},
        SliderCrankGeometry{30.0, 90.0, 10.0, true}}) {
    const auto m = makeSliderCrank(g);
    REQUIRE(m);
    const auto s = asSliderCrank(*m);
    REQUIRE(s);
    const auto back = sliderCrankGeometry(*m, *s);
    REQUIRE(back);
    CHECK(back->crank == Approx(g.crank));
    CHECK(back->rod == Approx(g.rod));
    // Read in the guide's own direction: a reversed guide (along −x) sees the offset mirrored.
    CHECK(back->offset == Approx(g.reversed ? -g.offset : g.offset));
    CHECK_FALSE(back->reversed);
  }
}
