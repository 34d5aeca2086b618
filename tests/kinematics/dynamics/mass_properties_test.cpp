// Validation of masses and loads (mass_properties.h) and the length units forces accept.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <limits>

using namespace linkwright::kinematics;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("metresPerLengthUnit knows m, cm, mm, in and ft", "[dynamics]") {
  CHECK(metresPerLengthUnit("m") == 1.0);
  CHECK(metresPerLengthUnit("cm") == 0.01);
  CHECK(metresPerLengthUnit("mm") == 0.001);
  CHECK(metresPerLengthUnit("in") == 0.0254);
  CHECK(metresPerLengthUnit("ft") == 0.3048);
  CHECK_FALSE(metresPerLengthUnit("furlong").has_value());
  CHECK_FALSE(metresPerLengthUnit("MM").has_value());
}

TEST_CASE("checkDynamics accepts every test case and an empty description", "[dynamics]") {
  for (const auto& c : linkwright::test::dynamicsCases()) {
    CAPTURE(c.name);
    CHECK_FALSE(checkDynamics(c.mechanism, c.dynamics).has_value());
  }
  const Mechanism m = makeFourBar({30.0, 10.0, 35.0, 20.0}, Branch::Open).value();
  CHECK_FALSE(checkDynamics(m, {}).has_value());
  CHECK(LinkageDynamics{}.empty());
}

TEST_CASE("checkDynamics names the bad field and value", "[dynamics]") {
  const Mechanism fourBar =
      makeFourBar({30.0, 10.0, 35.0, 20.0}, Branch::Open, "mm", CouplerPointSpec{10.0, 5.0}).value();
  const Mechanism slider = makeSliderCrank(kLs3Engine).value();
  const Mechanism yoke = linkwright::test::prpYoke();
  auto withLink = [](LinkMass l) {
    LinkageDynamics d;
    d.links = {{"crank", 0.1, std::nullopt, std::nullopt}, l};
    return d;
  };
  auto withForce = [](PointForce f) {
    LinkageDynamics d;
    d.loads.forces = {f};
    return d;
  };
  struct Row {
    const Mechanism* mechanism;
    LinkageDynamics dynamics;
    std::string field;
    std::string message;
  };
  const std::vector<Row> rows{
      {&fourBar, withLink({"coupler", kNaN, std::nullopt, std::nullopt}), "links[1].mass",
       "links[1].mass must be between 0 and 1e9 kg (got undefined)"},
      {&fourBar, withLink({"coupler", -0.5, std::nullopt, std::nullopt}), "links[1].mass",
       "links[1].mass must be between 0 and 1e9 kg (got -0.5)"},
      {&fourBar, withLink({"coupler", 1.0, std::nullopt, -1e-3}), "links[1].inertia",
       "links[1].inertia must be between 0 and 1e27 kg·m² (got -0.001)"},
      {&fourBar, withLink({"coupler", 1.0, std::nullopt, kInf}), "links[1].inertia",
       "links[1].inertia must be between 0 and 1e27 kg·m² (got undefined)"},
      {&fourBar, withLink({"coupler", 1.0, LinkFramePoint{kInf, 0.0}, std::nullopt}), "links[1].centre.along",
       "links[1].centre.along must be finite (got undefined)"},
      {&fourBar, withLink({"bar", 1.0, std::nullopt, std::nullopt}), "links[1].link",
       "links[1].link names no link of this mechanism (got \"bar\")"},
      {&fourBar, withLink({"crank", 1.0, std::nullopt, std::nullopt}), "links[1].link",
       "links[1].link repeats the link \"crank\""},
      {&slider, LinkageDynamics{{}, {{"B", 0, 1.0, 0.0}}, {}}, "sliders[0].point",
       "sliders[0].point must name a slider's point (an rrp, rpr or prp point; got \"B\")"},
      {&slider, LinkageDynamics{{}, {{"C", 1, 1.0, 0.0}}, {}}, "sliders[0].guide",
       "sliders[0].guide must be 0 for C (got 1)"},
      {&yoke, LinkageDynamics{{}, {{"C", 2, 1.0, 0.0}}, {}}, "sliders[0].guide",
       "sliders[0].guide must be 0 or 1 for C (got 2)"},
      {&slider, LinkageDynamics{{}, {{"C", 0, -2.0, 0.0}}, {}}, "sliders[0].mass",
       "sliders[0].mass must be between 0 and 1e9 kg (got -2)"},
      {&fourBar, LinkageDynamics{{}, {}, {Eigen::Vector2d(0.0, kNaN), {}, {}}}, "loads.gravity.y",
       "loads.gravity.y must be finite and within ±1e6 m/s² (got undefined)"},
      {&fourBar, LinkageDynamics{{}, {}, {std::nullopt, {{"rocker", kNaN}}, {}}}, "loads.torques[0].torque",
       "loads.torques[0].torque must be finite and within ±1e33 N·m (got undefined)"},
      {&fourBar, LinkageDynamics{{}, {}, {std::nullopt, {{"output", 1.0}}, {}}}, "loads.torques[0].link",
       "loads.torques[0].link names no link of this mechanism (got \"output\")"},
      {&fourBar, withForce({"coupler", "O4", 0, Eigen::Vector2d(1.0, 0.0)}), "loads.forces[0].point",
       "loads.forces[0].point must lie on the body of link coupler (got \"O4\")"},
      {&fourBar, withForce({"coupler", "Q", 0, Eigen::Vector2d(1.0, 0.0)}), "loads.forces[0].point",
       "loads.forces[0].point names no point of this mechanism (got \"Q\")"},
      {&fourBar, withForce({"coupler", "P", 0, Eigen::Vector2d(kInf, 0.0)}), "loads.forces[0].force.x",
       "loads.forces[0].force.x must be finite and within ±1e24 N (got undefined)"},
      {&slider, withForce({"", "B", 0, Eigen::Vector2d(1.0, 0.0)}), "loads.forces[0].point",
       "loads.forces[0].point must name a slider's point (an rrp, rpr or prp point; got \"B\")"},
  };
  for (const Row& row : rows) {
    CAPTURE(row.message);
    const auto e = checkDynamics(*row.mechanism, row.dynamics);
    REQUIRE(e.has_value());
    CHECK(e->field == row.field);
    CHECK(e->message == row.message);
    CHECK(e->code == ErrorCode::InvalidValue);
  }
  // A force at the coupler point P on the coupler is fine: P rides on the coupler.
  CHECK_FALSE(checkDynamics(fourBar, withForce({"coupler", "P", 0, Eigen::Vector2d(1.0, 0.0)})).has_value());
}
