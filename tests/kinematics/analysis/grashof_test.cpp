// Tests kinematics/analysis/grashof.h: every class with the shortest link in each place, the
// S+L and P+Q sums, which links turn fully, the change-point tolerance and the names.

#include "kinematics/analysis/grashof.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <string>

using namespace linkwright::kinematics;

TEST_CASE("classifyGrashof: the thesis linkage is a crank-rocker (S+L 95 < P+Q 105)", "[grashof]") {
  const GrashofReport r = classifyGrashof(linkwright::test::kThesis);
  CHECK(r.category == GrashofClass::CrankRocker);
  CHECK(r.shortest == LinkRole::Crank);
  CHECK(r.longest == LinkRole::Coupler);
  CHECK(r.sPlusL == 95.0);
  CHECK(r.pPlusQ == 105.0);
  CHECK(r.inputFullyRotates);
  CHECK_FALSE(r.outputFullyRotates);
}

TEST_CASE("classifyGrashof: each class, by where the shortest link is", "[grashof]") {
  using C = GrashofClass;
  using R = LinkRole;
  // frame, crank, coupler, rocker | class, shortest, longest, S+L, P+Q, input turns, output turns
  const auto [frame, crank, coupler, rocker, category, shortest, longest, sPlusL, pPlusQ, inputTurns, outputTurns] =
      GENERATE(table<double, double, double, double, C, R, R, double, double, bool, bool>({
          {60, 25, 70, 45, C::CrankRocker, R::Crank, R::Coupler, 95, 105, true, false},
          {80, 20, 66, 56, C::CrankRocker, R::Crank, R::Frame, 100, 122, true, false},    // Alvi
          {60, 45, 70, 25, C::CrankRocker, R::Rocker, R::Coupler, 95, 105, false, true},  // rocker-crank
          {25, 60, 45, 70, C::DoubleCrank, R::Frame, R::Rocker, 95, 105, true, true},
          {60, 45, 25, 70, C::DoubleRocker, R::Coupler, R::Rocker, 95, 105, false, false},
          {60, 50, 35, 40, C::TripleRocker, R::Coupler, R::Frame, 95, 90, false, false},
          {50, 40, 80, 20, C::TripleRocker, R::Rocker, R::Coupler, 100, 90, false, false},
          // Parallelogram: crank and rocker are both shortest and both turn fully with each other.
          {60, 25, 60, 25, C::ChangePoint, R::Crank, R::Frame, 85, 85, true, true},
          {60, 25, 25, 60, C::ChangePoint, R::Crank, R::Frame, 85, 85, true, false},  // kite
          {30, 30, 30, 30, C::ChangePoint, R::Frame, R::Frame, 60, 60, true, true},   // rhombus
      }));
  CAPTURE(frame, crank, coupler, rocker);
  const GrashofReport r = classifyGrashof({frame, crank, coupler, rocker});
  CHECK(toString(r.category) == toString(category));
  CHECK(toString(r.shortest) == toString(shortest));
  CHECK(toString(r.longest) == toString(longest));
  CHECK(r.sPlusL == sPlusL);
  CHECK(r.pPlusQ == pPlusQ);
  CHECK(r.inputFullyRotates == inputTurns);
  CHECK(r.outputFullyRotates == outputTurns);
}

TEST_CASE("classifyGrashof: the change point uses a tolerance relative to the total length", "[grashof]") {
  for (const double scale : {1e-3, 1.0, 1e3, 1e6}) {
    CAPTURE(scale);
    const auto at = [scale](double frameFactor, double rockerFactor) {
      return classifyGrashof({60.0 * scale * frameFactor, 25.0 * scale, 60.0 * scale, 25.0 * scale * rockerFactor})
          .category;
    };
    // kChangePointTolerance is 1e-9 of the total (170·scale): a length off by 1e-11 relative
    // (≤ 6e-10 of 60) is a round-off change point, one off by 1e-6 (≥ 2.5e-5) a real linkage.
    CHECK(at(1.0, 1.0) == GrashofClass::ChangePoint);
    CHECK(at(1.0 + 1e-11, 1.0) == GrashofClass::ChangePoint);
    CHECK(at(1.0, 1.0 - 1e-11) == GrashofClass::ChangePoint);
    // A longer frame makes L + S exceed P + Q; a shorter or longer rocker keeps S + L < P + Q.
    CHECK(at(1.0 + 1e-6, 1.0) == GrashofClass::TripleRocker);
    CHECK(at(1.0, 1.0 + 1e-6) == GrashofClass::CrankRocker);  // crank shortest
    CHECK(at(1.0, 1.0 - 1e-6) == GrashofClass::CrankRocker);  // rocker shortest
    CHECK(classifyGrashof({60.0 * scale, 25.0 * scale, 60.0 * scale, 25.0 * scale * (1.0 - 1e-6)}).shortest ==
          LinkRole::Rocker);
  }
  // An explicit tolerance widens or narrows the band.
  CHECK(classifyGrashof({60.0, 25.0, 60.0, 25.01}, 1e-3).category == GrashofClass::ChangePoint);
  CHECK(classifyGrashof({60.0, 25.0, 60.0, 25.01}, 1e-6).category == GrashofClass::CrankRocker);
}

TEST_CASE("classifyGrashof: the margin sign decides between Grashof and non-Grashof", "[grashof]") {
  // The thesis linkage with other frames. S = 25 (crank); for frame ≤ 70, L = 70 and the test
  // is 95 vs 45 + frame, so Grashof iff frame > 50.
  CHECK(classifyGrashof({49.0, 25.0, 70.0, 45.0}).category == GrashofClass::TripleRocker);
  CHECK(classifyGrashof({50.0, 25.0, 70.0, 45.0}).category == GrashofClass::ChangePoint);
  CHECK(classifyGrashof({51.0, 25.0, 70.0, 45.0}).category == GrashofClass::CrankRocker);
  // For frame > 70: 25 + frame vs 115 → Grashof iff frame < 90.
  CHECK(classifyGrashof({89.0, 25.0, 70.0, 45.0}).category == GrashofClass::CrankRocker);
  CHECK(classifyGrashof({90.0, 25.0, 70.0, 45.0}).category == GrashofClass::ChangePoint);
  CHECK(classifyGrashof({91.0, 25.0, 70.0, 45.0}).category == GrashofClass::TripleRocker);
}

TEST_CASE("Grashof names", "[grashof]") {
  CHECK(toString(GrashofClass::CrankRocker) == "crank-rocker");
  CHECK(toString(GrashofClass::DoubleCrank) == "double-crank");
  CHECK(toString(GrashofClass::DoubleRocker) == "double-rocker");
  CHECK(toString(GrashofClass::ChangePoint) == "change-point");
  CHECK(toString(GrashofClass::TripleRocker) == "triple-rocker");
  CHECK(toString(LinkRole::Frame) == "frame");
  CHECK(toString(LinkRole::Crank) == "crank");
  CHECK(toString(LinkRole::Coupler) == "coupler");
  CHECK(toString(LinkRole::Rocker) == "rocker");
}
