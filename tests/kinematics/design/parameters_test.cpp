// Tests kinematics/design/parameters.h: every parameter of every example reads back what was
// set and changes that one number only; each kind of point lists the numbers that define it;
// a parameter the mechanism does not have is refused.

#include "kinematics/design/parameters.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"

#include "tests/support/catch.h"

#include <algorithm>

using namespace linkwright::kinematics;

TEST_CASE("every parameter of every example reads back what was set, and nothing else moves", "[parameters]") {
  std::vector<Mechanism> mechanisms{
      *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, -20.0})};
  for (const Example& e : examples()) mechanisms.push_back(e.mechanism);
  for (const Mechanism& m : mechanisms) {
    const std::vector<Parameter> parameters = parametersOf(m);
    REQUIRE_FALSE(parameters.empty());
    for (const Parameter& p : parameters) {
      CAPTURE(m.points[p.point.index].name, static_cast<int>(p.slot), p.constraint);
      const auto before = parameterValue(m, p);
      REQUIRE(before.has_value());
      Mechanism changed = m;
      REQUIRE(setParameter(changed, p, *before + 0.5));
      CHECK(parameterValue(changed, p) == *before + 0.5);
      CHECK(changed != m);
      for (const Parameter& other : parameters)
        if (!(other == p)) CHECK(parameterValue(changed, other) == parameterValue(m, other));
      REQUIRE(setParameter(changed, p, *before));
      CHECK(changed == m);  // the same number, nothing else
    }
  }
}

TEST_CASE("each kind of point lists the numbers that define it", "[parameters]") {
  using S = ParameterSlot;
  const Mechanism fourBar = *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, -20.0});
  const std::vector<Parameter> expected{
      {PointId{0}, S::X},      {PointId{0}, S::Y},     {PointId{1}, S::X},      {PointId{1}, S::Y},
      {PointId{2}, S::Length}, {PointId{2}, S::Phase}, {PointId{3}, S::Length}, {PointId{3}, S::SecondLength},
      {PointId{4}, S::Along},  {PointId{4}, S::Across}};
  CHECK(parametersOf(fourBar) == expected);
  CHECK(parameterUnit(S::Length) == ParameterUnit::Length);
  CHECK(parameterUnit(S::ConstraintLength) == ParameterUnit::Length);
  CHECK(parameterUnit(S::GuideAngle) == ParameterUnit::Angle);
  CHECK(parameterUnit(S::Along) == ParameterUnit::Offset);

  // A free point lists its guess, then each constraint whose later point it is, once.
  const auto triad = findExample("stephenson-ii");
  REQUIRE(triad.has_value());
  const std::vector<Parameter> all = parametersOf(triad->mechanism);
  for (std::size_t c = 0; c < triad->mechanism.constraints.size(); ++c)
    CHECK(std::count(all.begin(), all.end(),
                     Parameter{PointId{std::max(triad->mechanism.constraints[c].first.index,
                                                triad->mechanism.constraints[c].second.index)},
                               S::ConstraintLength, c}) == 1);
}

TEST_CASE("a parameter the mechanism does not have is refused and changes nothing", "[parameters][errors]") {
  Mechanism m = *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open);
  const Mechanism before = m;
  for (const Parameter& p : {Parameter{PointId{0}, ParameterSlot::Length}, Parameter{PointId{9}, ParameterSlot::X},
                             Parameter{PointId{3}, ParameterSlot::GuideAngle}}) {
    CHECK_FALSE(parameterValue(m, p).has_value());
    CHECK_FALSE(setParameter(m, p, 1.0));
  }
  CHECK(m == before);
}
