// Tests kinematics/design/derived_design.h: one verdict per candidate design. An accepted
// design carries its recognised four-bar and the analysis of its grid (checked against the
// pieces computed on their own: the structure, the closed forms, an independent sweep); a
// refused one carries the one sentence for why, whether the fault is a field, a four-bar's
// lengths or a linkage whose every grid sample fails.

#include "kinematics/design/derived_design.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;

TEST_CASE("an accepted four-bar carries its structure and its closed-form analysis", "[design][derive]") {
  const Design d = *fourBarDesign(kThesisCrankRocker);
  // The thesis four-bar's crank turns fully: no grid is read.
  CHECK_FALSE(needsGridSweep(d.mechanism));
  const auto derived = deriveDesign(d);
  REQUIRE(derived);
  REQUIRE(derived->fourBar);
  CHECK(derived->fourBar->lengths == kThesisCrankRocker);
  CHECK(derived->analysis.inputRange.fullRotation);
  REQUIRE(derived->analysis.grashof);
  CHECK(derived->analysis.grashof->category == GrashofClass::CrankRocker);
  CHECK(derived->analysis.grashof->inputFullyRotates);
  // The same verdict from the overload that is handed an empty grid.
  const auto handed = deriveDesign(d, SweepResult{});
  REQUIRE(handed);
  CHECK(handed->analysis.inputRange == derived->analysis.inputRange);
}

TEST_CASE("a rocking four-bar and any other linkage are derived from their grid", "[design][derive]") {
  // 60/25/30/45 cannot turn its crank fully: its gaps are the grid's.
  const Design rocking = *fourBarDesign({60.0, 25.0, 30.0, 45.0});
  CHECK(needsGridSweep(rocking.mechanism));
  const auto fromFourBar = deriveDesign(rocking);
  REQUIRE(fromFourBar);
  CHECK_FALSE(fromFourBar->analysis.notAssembled.empty());
  // The shaper: its analysis equals the one of a grid swept here on its own.
  const Design shaper = *designForExample("shaper");
  CHECK(needsGridSweep(shaper.mechanism));
  const auto grid = sweep(shaper.mechanism, designSweepSpec(shaper), gridSweepRequest());
  REQUIRE(grid);
  const auto swept = deriveDesign(shaper);
  const auto handed = deriveDesign(shaper, *grid);
  REQUIRE(swept);
  REQUIRE(handed);
  CHECK_FALSE(swept->fourBar);
  CHECK(swept->analysis.inputRange == assembledRange(*grid));
  CHECK(swept->analysis.inputRange == handed->analysis.inputRange);
  CHECK(swept->analysis.quickReturn.has_value());
}

TEST_CASE("a refused design gives the one sentence for its reason", "[design][derive][refusal]") {
  SECTION("a field out of its range, named") {
    Design d = *fourBarDesign(kThesisCrankRocker);
    d.samples = 1;
    const auto derived = deriveDesign(d);
    REQUIRE_FALSE(derived);
    CHECK(derived.error().field == "samples");
  }
  SECTION("a four-bar whose coupler and rocker cannot reach, by its closed form") {
    const auto derived = deriveDesign(*fourBarDesign({60.0, 25.0, 5.0, 5.0}));
    REQUIRE_FALSE(derived);
    CHECK(derived.error().code == ErrorCode::NotAssemblable);
    CHECK(derived.error().field == "design");
    CHECK(derived.error().message ==
          "This linkage cannot be assembled at any crank angle: the coupler and rocker cannot reach between the "
          "crank tip and the rocker pivot.");
  }
  SECTION("a slider-crank whose rod never reaches its guide, by its grid") {
    // Crank 10 and rod 20 reach at most 30 from O2; the guide is 50 away.
    Design d;
    d.kind = "slider-crank";
    d.mechanism = *makeSliderCrank({10.0, 20.0, 50.0});
    d.samples = 73;
    CHECK(needsGridSweep(d.mechanism));
    const auto derived = deriveDesign(d);
    REQUIRE_FALSE(derived);
    CHECK(derived.error().code == ErrorCode::NotAssemblable);
    CHECK(derived.error().message.starts_with("This linkage cannot be assembled at any crank angle: "));
  }
}
