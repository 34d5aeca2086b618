// Tests kinematics/design/parameters.h: every parameter of every example reads back what was
// set and changes that one number only; each kind of point lists the numbers that define it;
// a parameter the mechanism does not have is refused.

#include "kinematics/design/parameters.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/model/work_count.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("every parameter of every example reads back what was set, and nothing else moves", "[parameters]") {
  // A four-bar's named dimensions are derived from its points' numbers: set and read back
  // through a sine and cosine, they agree to round-off, not bit for bit.
  const auto same = [](std::optional<double> a, std::optional<double> b) {
    return a && b && std::abs(*a - *b) <= 1e-12 * std::max(1.0, std::abs(*b));
  };
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
      CHECK(same(parameterValue(changed, p), *before + 0.5));
      CHECK(changed != m);
      // A four-bar's frame runs from O2 to O4: moving O2 changes the frame's length and
      // direction, as a drag of O2 does; nothing else.
      const auto fourBar = asFourBar(m);
      const bool movesFrame = fourBar && p.point == fourBar->o2;
      for (const Parameter& other : parameters)
        if (!(other == p) &&
            !(movesFrame && (other.slot == ParameterSlot::FrameLength || other.slot == ParameterSlot::FrameAngle)))
          CHECK(same(parameterValue(changed, other), parameterValue(m, other)));
      REQUIRE(setParameter(changed, p, *before));
      if (isFourBarDimension(p.slot)) {
        for (const Parameter& other : parameters) CHECK(same(parameterValue(changed, other), parameterValue(m, other)));
      } else {
        CHECK(changed == m);  // the same number, nothing else
      }
    }
  }
}

TEST_CASE("each kind of point lists the numbers that define it", "[parameters]") {
  using S = ParameterSlot;
  const Mechanism fourBar = *makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, -20.0});
  // A four-bar by its named lengths first; the frame's direction stands for O4's x and y.
  const std::vector<Parameter> expected{
      {PointId{1}, S::FrameLength},  {PointId{2}, S::CrankLength}, {PointId{3}, S::CouplerLength},
      {PointId{3}, S::RockerLength}, {PointId{0}, S::X},           {PointId{0}, S::Y},
      {PointId{1}, S::FrameAngle},   {PointId{2}, S::Phase},       {PointId{4}, S::Along},
      {PointId{4}, S::Across}};
  CHECK(parametersOf(fourBar) == expected);
  CHECK(parameterUnit(S::RockerLength) == ParameterUnit::Length);
  CHECK(parameterUnit(S::FrameAngle) == ParameterUnit::Angle);
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

TEST_CASE("a four-bar's named dimensions set the linkage as withFourBarLengths does, however it is stored",
          "[parameters][fourbar]") {
  using S = ParameterSlot;
  // The triple rocker 60/50/35/40 drawn with its frame at 30°, C's parents as (O4, B), a point
  // on a coupler link that runs C→B.
  const FourBarLengths l{60.0, 50.0, 35.0, 40.0};
  const double f = 30.0 * kPi / 180.0;
  Mechanism m;
  m.points = {{"O2", GroundPoint{Eigen::Vector2d(-30.0, 12.0)}},
              {"O4", GroundPoint{Eigen::Vector2d(-30.0, 12.0) + l.frame * Eigen::Vector2d(std::cos(f), std::sin(f))}},
              {"B", CrankPoint{PointId{0}, l.crank, 0.0}},
              {"C", RrrPoint{PointId{1}, l.rocker, PointId{2}, l.coupler, Branch::Crossed}},
              {"P", AttachedPoint{LinkId{1}, 10.0, 4.0}}};
  m.links = {
      {"crank", PointId{0}, PointId{2}}, {"coupler", PointId{3}, PointId{2}}, {"rocker", PointId{1}, PointId{3}}};
  const auto s = asFourBar(m);
  REQUIRE(s);
  const PointId o4{1};
  const PointId c{3};
  CHECK(parameterValue(m, {o4, S::FrameLength}) == s->lengths.frame);
  CHECK(parameterValue(m, {c, S::RockerLength}) == 40.0);
  CHECK(parameterValue(m, {c, S::CouplerLength}) == 35.0);
  CHECK(std::abs(*parameterValue(m, {o4, S::FrameAngle}) - f) < 1e-15);
  // The coupler through setParameter is the coupler through withFourBarLengths: one path.
  Mechanism viaParameter = m;
  REQUIRE(setParameter(viaParameter, {c, S::CouplerLength}, 42.0));
  FourBarLengths longer = s->lengths;
  longer.coupler = 42.0;
  CHECK(viaParameter == withFourBarLengths(m, *s, longer));
  CHECK(asFourBar(viaParameter)->lengths.coupler == 42.0);
  // Turning the frame moves O4 about O2 at the frame's length.
  Mechanism turned = m;
  REQUIRE(setParameter(turned, {o4, S::FrameAngle}, 0.0));
  const auto& o4At = std::get<GroundPoint>(turned.points[1].definition).position;
  CHECK(std::abs(o4At.x() - (-30.0 + s->lengths.frame)) < 1e-12);
  CHECK(o4At.y() == 12.0);
  // A named dimension on the wrong point, or on a linkage that is no four-bar, is no parameter.
  CHECK_FALSE(parameterValue(m, {PointId{2}, S::CouplerLength}));
  Mechanism notFourBar = m;
  notFourBar.points.push_back({"Q", GroundPoint{Eigen::Vector2d(0.0, 0.0)}});
  notFourBar.points[3].definition = RrrPoint{PointId{1}, l.rocker, PointId{5}, l.coupler, Branch::Crossed};
  CHECK_FALSE(setParameter(notFourBar, {c, S::CouplerLength}, 42.0));
}

TEST_CASE("parameterValues reads every parameter as parameterValue does, recognising the linkage once",
          "[parameters]") {
  for (const Example& e : examples()) {
    CAPTURE(e.name);
    std::vector<Parameter> parameters = parametersOf(e.mechanism);
    // One the mechanism does not have: nothing, as parameterValue says.
    parameters.push_back({PointId{e.mechanism.points.size() + 3}, ParameterSlot::X});
    const WorkCount before = workCount();
    const auto values = parameterValues(e.mechanism, parameters);
    CHECK((workCount() - before).recognitions <= 1);
    REQUIRE(values.size() == parameters.size());
    for (std::size_t i = 0; i < parameters.size(); ++i) CHECK(values[i] == parameterValue(e.mechanism, parameters[i]));
    CHECK_FALSE(values.back());
    CHECK(parameterValues(e.mechanism, parameters, asFourBar(e.mechanism, PointsOnLinks::AnyLink)) == values);
  }
}
