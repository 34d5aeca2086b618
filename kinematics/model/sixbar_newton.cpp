#include "kinematics/model/sixbar_newton.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/validate.h"

#include <initializer_list>
#include <utility>

namespace linkwright::kinematics {
namespace {

std::optional<Error> checkPoint(const Eigen::Vector2d& p, const std::string& field) {
  if (auto e = checkCoordinate(p.x(), field + ".x")) return e;
  return checkCoordinate(p.y(), field + ".y");
}

std::optional<Error> checkLengths(std::initializer_list<std::pair<double, const char*>> lengths) {
  for (const auto& [value, field] : lengths)
    if (auto e = checkLength(value, field)) return e;
  return std::nullopt;
}

std::optional<Error> checkGeometry(const StephensonIIIGeometry& g) {
  if (auto e = checkPoint(g.o4, "o4")) return e;
  if (auto e = checkPoint(g.o6, "o6")) return e;
  if (auto e = checkLengths({{g.crank, "crank"},
                             {g.coupler, "coupler"},
                             {g.cd, "cd"},
                             {g.ce, "ce"},
                             {g.de, "de"},
                             {g.rocker4, "rocker4"},
                             {g.rocker6, "rocker6"}}))
    return e;
  if (auto e = checkPoint(g.guessC, "guessC")) return e;
  if (auto e = checkPoint(g.guessD, "guessD")) return e;
  return checkPoint(g.guessE, "guessE");
}

std::optional<Error> checkGeometry(const StephensonIIGeometry& g) {
  if (auto e = checkPoint(g.j5, "j5")) return e;
  if (auto e = checkLengths({{g.crank, "crank"},
                             {g.j1j2, "j1j2"},
                             {g.j1j3, "j1j3"},
                             {g.j2j3, "j2j3"},
                             {g.j5j4, "j5j4"},
                             {g.j5j6, "j5j6"},
                             {g.j4j6, "j4j6"},
                             {g.link5, "link5"},
                             {g.link6, "link6"}}))
    return e;
  if (auto e = checkPoint(g.guessJ2, "guessJ2")) return e;
  if (auto e = checkPoint(g.guessJ3, "guessJ3")) return e;
  if (auto e = checkPoint(g.guessJ4, "guessJ4")) return e;
  return checkPoint(g.guessJ6, "guessJ6");
}

}  // namespace

Result<Mechanism> makeStephensonIIINewton(const StephensonIIIGeometry& g, const std::string& lengthUnit) {
  if (auto e = checkGeometry(g)) return *e;
  using namespace stephenson3;
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"O2", GroundPoint{Eigen::Vector2d::Zero()}},
      {"O4", GroundPoint{g.o4}},
      {"O6", GroundPoint{g.o6}},
      {"B", CrankPoint{kO2, g.crank, 0.0}},
      {"C", FreePoint{g.guessC}},
      {"D", FreePoint{g.guessD}},
      {"E", FreePoint{g.guessE}},
  };
  m.links = {
      {"crank", kO2, kB}, {"coupler", kB, kC}, {"ternary", kC, kD}, {"rocker4", kO4, kD}, {"rocker6", kO6, kE},
  };
  m.constraints = {
      {kB, kC, g.coupler}, {kC, kD, g.cd}, {kC, kE, g.ce}, {kD, kE, g.de}, {kO4, kD, g.rocker4}, {kO6, kE, g.rocker6},
  };
  if (auto e = checkLinkageScale(m)) return *e;
  return m;
}

Result<Mechanism> makeStephensonIINewton(const StephensonIIGeometry& g, const std::string& lengthUnit) {
  if (auto e = checkGeometry(g)) return *e;
  using namespace stephenson2;
  Mechanism m;
  m.lengthUnit = lengthUnit;
  m.points = {
      {"J0", GroundPoint{Eigen::Vector2d::Zero()}},
      {"J5", GroundPoint{g.j5}},
      {"J1", CrankPoint{kJ0, g.crank, 0.0}},
      {"J2", FreePoint{g.guessJ2}},
      {"J3", FreePoint{g.guessJ3}},
      {"J4", FreePoint{g.guessJ4}},
      {"J6", FreePoint{g.guessJ6}},
  };
  m.links = {
      {"crank", kJ0, kJ1}, {"coupler", kJ1, kJ2}, {"rocker", kJ5, kJ4}, {"link5", kJ3, kJ4}, {"link6", kJ2, kJ6},
  };
  m.constraints = {
      {kJ1, kJ2, g.j1j2}, {kJ1, kJ3, g.j1j3}, {kJ2, kJ3, g.j2j3},  {kJ5, kJ4, g.j5j4},
      {kJ5, kJ6, g.j5j6}, {kJ4, kJ6, g.j4j6}, {kJ3, kJ4, g.link5}, {kJ2, kJ6, g.link6},
  };
  if (auto e = checkLinkageScale(m)) return *e;
  return m;
}

}  // namespace linkwright::kinematics
