// View ▸ Instant centres on the canvas (ui/canvas/instant_centres_item.h): what the item draws
// is the core's instant centres at the document's pose (the `centres` command's numbers) and
// follows the crank; its moving centrode, placed with the coupler, touches the fixed one at
// I13 at every sample of the cycle; a six-bar's and a shaper's fifteen centres are all drawn;
// centres Kennedy's theorem does not reach are named; hidden, nothing is solved.

#include "ui/canvas/instant_centres_item.h"

#include "tests/ui/canvas/canvas_test_support.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

using namespace linkwright;
namespace k = kinematics;

namespace {

const ui::InstantCentresItem& centresItem(ui::test::ShownView& v) { return *v.scene().instantCentresItem(); }

}  // namespace

TEST_CASE("the canvas's instant centres are the core's at the crank angle shown, and follow it",
          "[ui][canvas][centres]") {
  const std::string example =
      GENERATE(std::string("thesis-crank-rocker"), std::string("alvi-fourbar"), std::string("ls3-engine"));
  CAPTURE(example);
  ui::test::ShownView v(*k::designForExample(example));
  CHECK_FALSE(centresItem(v).isVisible());
  CHECK_FALSE(centresItem(v).centres().has_value());  // hidden: nothing solved
  v.view.setShowInstantCentres(true);
  REQUIRE(centresItem(v).isVisible());
  for (const double deg : {0.0, 37.0, 90.0, 215.0}) {
    CAPTURE(deg);
    v.document.setCrankAngle(k::degToRad(deg));
    const auto expected = k::instantCentres(v.document.mechanism(), v.document.pose());
    REQUIRE(expected);
    REQUIRE(centresItem(v).centres().has_value());
    CHECK(*centresItem(v).centres() == *expected);
    CHECK(centresItem(v).reason().isEmpty());
  }
  // The moving centrode rolls on the fixed one: with the coupler where it is at each sample of
  // the cycle, its point from that sample lies on the fixed centrode's point from that sample.
  const k::Centrodes& curves = centresItem(v).centrodes();
  REQUIRE_FALSE(curves.fixed.empty());
  const k::SweepResult& sweep = v.document.sweep();
  const double size = v.scene().linkageSize();
  std::size_t run = 0, i = 0;
  for (std::size_t j = 0; j < sweep.size() && run < curves.fixed.size(); ++j) {
    if (!sweep.assembled(j)) continue;
    k::Pose pose;
    for (const auto& column : sweep.position) pose.position.push_back(column[j]);
    const auto frame = k::couplerFrame(v.document.mechanism(), pose);
    const auto centres = k::instantCentres(v.document.mechanism(), pose);
    REQUIRE(frame);
    REQUIRE(centres);
    if (centres->centre(1, 3).kind != k::CentreKind::Finite ||
        (centres->centre(1, 3).position - centres->anchor).norm() > k::kCentrodeReach * centres->scale)
      continue;
    CHECK((frame->toWorld(curves.moving[run][i]) - curves.fixed[run][i]).norm() <= 1e-9 * size);
    CHECK((curves.fixed[run][i] - centres->centre(1, 3).position).norm() <= 1e-9 * size);
    if (++i == curves.fixed[run].size()) {
      ++run;
      i = 0;
    }
  }
}

TEST_CASE("a six-bar's and a shaper's fifteen centres are drawn, every one located", "[ui][canvas][centres]") {
  for (const char* example : {"watt-ii", "shaper"}) {
    CAPTURE(example);
    ui::test::ShownView v(*k::designForExample(example));
    v.view.setShowInstantCentres(true);
    v.document.setCrankAngle(k::degToRad(40.0));
    const auto expected = k::instantCentres(v.document.mechanism(), v.document.pose());
    REQUIRE(expected);
    REQUIRE(centresItem(v).centres().has_value());
    CHECK(*centresItem(v).centres() == *expected);
    CHECK(centresItem(v).centres()->centres.size() == 15);
    CHECK(centresItem(v).unresolvedNote().isEmpty());
    CHECK_FALSE(centresItem(v).centrodes().fixed.empty());  // the coupler's (Watt), the link's (shaper)
    v.view.grab();                                          // paints without a crash
  }
}

TEST_CASE("centres Kennedy's theorem does not reach are named on the canvas", "[ui][canvas][centres]") {
  ui::test::ShownView v(*k::designForExample("seed-arm"));  // two freedoms: the frame–forearm centre I13 is free
  v.view.setShowInstantCentres(true);
  REQUIRE(centresItem(v).centres().has_value());
  CHECK(centresItem(v).reason().isEmpty());
  CHECK(centresItem(v).unresolvedNote() == QStringLiteral("I₁₃: Kennedy's theorem does not reach it"));
  CHECK(centresItem(v).centrodes().fixed.empty());
  v.view.grab();
}
