#include "kinematics/design/parameters.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/recognise.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace linkwright::kinematics {
namespace {

// The address of a number, const or not as the mechanism it lies in.
template <typename Owner>
using NumberPtr = std::conditional_t<std::is_const_v<Owner>, const double*, double*>;

template <typename G>
NumberPtr<G> guideNumber(G& g, int which) {  // 0 x / along, 1 y / across, 2 angle
  return which == 0 ? &g.point.x() : which == 1 ? &g.point.y() : &g.angle;
}

int guideIndex(ParameterSlot s) {
  switch (s) {
  case ParameterSlot::GuideX:
  case ParameterSlot::SecondGuideX: return 0;
  case ParameterSlot::GuideY:
  case ParameterSlot::SecondGuideY: return 1;
  default: return 2;
  }
}

bool firstGuide(ParameterSlot s) {
  return s == ParameterSlot::GuideX || s == ParameterSlot::GuideY || s == ParameterSlot::GuideAngle;
}
bool secondGuide(ParameterSlot s) {
  return s == ParameterSlot::SecondGuideX || s == ParameterSlot::SecondGuideY || s == ParameterSlot::SecondGuideAngle;
}

// A path's numbers: a polyline's vertices, an arc's centre, radius, start and sweep.
template <typename Shape>
NumberPtr<Shape> pathNumber(Shape& shape, const Parameter& p) {
  using S = ParameterSlot;
  if (auto* line = std::get_if<PolylinePath>(&shape)) {
    if (p.vertex >= line->vertices.size()) return nullptr;
    auto& v = line->vertices[p.vertex];
    return p.slot == S::PathX ? &v.x() : p.slot == S::PathY ? &v.y() : nullptr;
  }
  auto& arc = std::get<ArcPath>(shape);
  switch (p.slot) {
  case S::X: return &arc.centre.x();
  case S::Y: return &arc.centre.y();
  case S::Length: return &arc.radius;
  case S::Phase: return &arc.startAngle;
  case S::Sweep: return &arc.sweep;
  default: return nullptr;
  }
}

// The number behind a parameter: one table for reading and writing.
template <typename M>
NumberPtr<M> numberOf(M& m, const Parameter& p) {
  using S = ParameterSlot;
  if (p.point.index >= m.points.size()) return nullptr;
  auto& d = m.points[p.point.index].definition;
  if (auto* g = std::get_if<GroundPoint>(&d))
    return p.slot == S::X ? &g->position.x() : p.slot == S::Y ? &g->position.y() : nullptr;
  if (auto* c = std::get_if<CrankPoint>(&d))
    return p.slot == S::Length ? &c->length : p.slot == S::Phase ? &c->phase : nullptr;
  if (auto* driven = std::get_if<PathPoint>(&d)) return pathNumber(driven->path, p);
  if (auto* a = std::get_if<ActuatorPoint>(&d)) return p.slot == S::Length ? &a->length : nullptr;
  if (auto* r = std::get_if<RrrPoint>(&d))
    return p.slot == S::Length ? &r->firstLength : p.slot == S::SecondLength ? &r->secondLength : nullptr;
  if (auto* s = std::get_if<RrpPoint>(&d))
    return p.slot == S::Length ? &s->length : firstGuide(p.slot) ? guideNumber(s->guide, guideIndex(p.slot)) : nullptr;
  if (auto* s = std::get_if<RprPoint>(&d)) return p.slot == S::Length ? &s->length : nullptr;
  if (auto* pin = std::get_if<PrpPoint>(&d)) {
    if (firstGuide(p.slot)) return guideNumber(pin->first, guideIndex(p.slot));
    if (secondGuide(p.slot)) return guideNumber(pin->second, guideIndex(p.slot));
    return nullptr;
  }
  if (auto* a = std::get_if<AttachedPoint>(&d))
    return p.slot == S::Along ? &a->along : p.slot == S::Across ? &a->across : nullptr;
  if (auto* f = std::get_if<FreePoint>(&d)) {
    if (p.slot == S::X) return &f->guess.x();
    if (p.slot == S::Y) return &f->guess.y();
    if (p.slot == S::ConstraintLength && p.constraint < m.constraints.size())
      return &m.constraints[p.constraint].length;
  }
  return nullptr;
}

// The named dimension's number in `lengths`.
double* fourBarLength(FourBarLengths& lengths, ParameterSlot slot) {
  switch (slot) {
  case ParameterSlot::FrameLength: return &lengths.frame;
  case ParameterSlot::CrankLength: return &lengths.crank;
  case ParameterSlot::CouplerLength: return &lengths.coupler;
  case ParameterSlot::RockerLength: return &lengths.rocker;
  default: return nullptr;
  }
}

// The point that carries each named dimension, as parametersOf lists it.
PointId carrier(const FourBarStructure& s, ParameterSlot slot) {
  switch (slot) {
  case ParameterSlot::CrankLength: return s.b;
  case ParameterSlot::CouplerLength:
  case ParameterSlot::RockerLength: return s.c;
  default: return s.o4;
  }
}

// Whether the four-bar's named dimensions stand for this raw number.
bool replacedByName(const FourBarStructure& s, const Parameter& p) {
  using S = ParameterSlot;
  if (p.point == s.o4) return p.slot == S::X || p.slot == S::Y;
  if (p.point == s.b) return p.slot == S::Length;
  if (p.point == s.c) return p.slot == S::Length || p.slot == S::SecondLength;
  return false;
}

// The raw numbers of every point, in point order.
std::vector<Parameter> rawParameters(const Mechanism& m) {
  using S = ParameterSlot;
  std::vector<Parameter> out;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointId p{i};
    const auto add = [&](std::initializer_list<S> slots) {
      for (const S s : slots) out.push_back({p, s});
    };
    const auto& d = m.points[i].definition;
    if (std::holds_alternative<GroundPoint>(d)) add({S::X, S::Y});
    else if (std::holds_alternative<CrankPoint>(d)) add({S::Length, S::Phase});
    else if (const auto* driven = std::get_if<PathPoint>(&d)) {
      if (const auto* line = std::get_if<PolylinePath>(&driven->path)) {
        for (std::size_t v = 0; v < line->vertices.size(); ++v) {
          out.push_back({p, S::PathX, 0, v});
          out.push_back({p, S::PathY, 0, v});
        }
      } else {
        add({S::X, S::Y, S::Length, S::Phase, S::Sweep});
      }
    } else if (std::holds_alternative<ActuatorPoint>(d)) add({S::Length});
    else if (std::holds_alternative<RrrPoint>(d)) add({S::Length, S::SecondLength});
    else if (std::holds_alternative<RrpPoint>(d)) add({S::Length, S::GuideX, S::GuideY, S::GuideAngle});
    else if (std::holds_alternative<RprPoint>(d)) add({S::Length});
    else if (std::holds_alternative<PrpPoint>(d))
      add({S::GuideX, S::GuideY, S::GuideAngle, S::SecondGuideX, S::SecondGuideY, S::SecondGuideAngle});
    else if (std::holds_alternative<AttachedPoint>(d)) add({S::Along, S::Across});
    else if (std::holds_alternative<FreePoint>(d)) {
      add({S::X, S::Y});
      // Each constraint is listed once, under the later of its two points.
      for (std::size_t c = 0; c < m.constraints.size(); ++c)
        if (std::max(m.constraints[c].first.index, m.constraints[c].second.index) == i)
          out.push_back({p, S::ConstraintLength, c});
    }
  }
  return out;
}

// The four-bar `parameter` names a dimension of, if it is a named one of `m`'s four-bar.
std::optional<FourBarStructure> namedFourBar(const Mechanism& m, const Parameter& parameter) {
  if (!isFourBarDimension(parameter.slot)) return std::nullopt;
  auto s = asFourBar(m, PointsOnLinks::AnyLink);
  if (!s || carrier(*s, parameter.slot) != parameter.point) return std::nullopt;
  return s;
}

}  // namespace

bool isFourBarDimension(ParameterSlot slot) {
  using S = ParameterSlot;
  return slot == S::FrameLength || slot == S::CrankLength || slot == S::CouplerLength || slot == S::RockerLength ||
         slot == S::FrameAngle;
}

std::vector<Parameter> parametersOf(const Mechanism& m) {
  return parametersOf(m, asFourBar(m, PointsOnLinks::AnyLink));
}

std::vector<Parameter> parametersOf(const Mechanism& m, const std::optional<FourBarStructure>& s) {
  using S = ParameterSlot;
  std::vector<Parameter> raw = rawParameters(m);
  if (!s) return raw;
  std::vector<Parameter> out;
  for (const S slot : {S::FrameLength, S::CrankLength, S::CouplerLength, S::RockerLength})
    out.push_back({carrier(*s, slot), slot});
  for (const Parameter& p : raw) {
    if (p.point == s->o4 && p.slot == S::X) out.push_back({s->o4, S::FrameAngle});
    if (!replacedByName(*s, p)) out.push_back(p);
  }
  return out;
}

ParameterUnit parameterUnit(ParameterSlot slot) {
  switch (slot) {
  case ParameterSlot::Length:
  case ParameterSlot::SecondLength:
  case ParameterSlot::ConstraintLength:
  case ParameterSlot::FrameLength:
  case ParameterSlot::CrankLength:
  case ParameterSlot::CouplerLength:
  case ParameterSlot::RockerLength: return ParameterUnit::Length;
  case ParameterSlot::FrameAngle:
  case ParameterSlot::Phase:
  case ParameterSlot::GuideAngle:
  case ParameterSlot::SecondGuideAngle:
  case ParameterSlot::Sweep: return ParameterUnit::Angle;
  default: return ParameterUnit::Offset;
  }
}

std::optional<double> parameterValue(const Mechanism& mechanism, const Parameter& parameter) {
  if (isFourBarDimension(parameter.slot)) {
    auto s = namedFourBar(mechanism, parameter);
    if (!s) return std::nullopt;
    if (parameter.slot == ParameterSlot::FrameAngle) return s->frameAngle;
    return *fourBarLength(s->lengths, parameter.slot);
  }
  if (const double* number = numberOf(mechanism, parameter)) return *number;
  return std::nullopt;
}

std::vector<std::optional<double>> parameterValues(const Mechanism& mechanism,
                                                   const std::vector<Parameter>& parameters) {
  const bool named =
      std::any_of(parameters.begin(), parameters.end(), [](const Parameter& p) { return isFourBarDimension(p.slot); });
  return parameterValues(mechanism, parameters, named ? asFourBar(mechanism, PointsOnLinks::AnyLink) : std::nullopt);
}

std::vector<std::optional<double>> parameterValues(const Mechanism& mechanism, const std::vector<Parameter>& parameters,
                                                   const std::optional<FourBarStructure>& s) {
  std::vector<std::optional<double>> values;
  values.reserve(parameters.size());
  for (const Parameter& p : parameters) {
    if (!isFourBarDimension(p.slot)) {
      const double* number = numberOf(mechanism, p);
      values.push_back(number ? std::optional<double>(*number) : std::nullopt);
    } else if (!s || carrier(*s, p.slot) != p.point) {
      values.emplace_back();
    } else if (p.slot == ParameterSlot::FrameAngle) {
      values.emplace_back(s->frameAngle);
    } else {
      FourBarLengths lengths = s->lengths;
      values.emplace_back(*fourBarLength(lengths, p.slot));
    }
  }
  return values;
}

bool setParameter(Mechanism& mechanism, const Parameter& parameter, double value) {
  if (isFourBarDimension(parameter.slot)) {
    auto s = namedFourBar(mechanism, parameter);
    if (!s) return false;
    if (parameter.slot == ParameterSlot::FrameAngle) {
      // O4 turns about O2, the frame's length kept.
      const Eigen::Vector2d o2 = std::get<GroundPoint>(mechanism.points[s->o2.index].definition).position;
      std::get<GroundPoint>(mechanism.points[s->o4.index].definition).position =
          o2 + s->lengths.frame * Eigen::Vector2d(std::cos(value), std::sin(value));
      return true;
    }
    FourBarLengths lengths = s->lengths;
    *fourBarLength(lengths, parameter.slot) = value;
    mechanism = withFourBarLengths(mechanism, *s, lengths);
    return true;
  }
  double* number = numberOf(mechanism, parameter);
  if (number == nullptr) return false;
  *number = value;
  return true;
}

}  // namespace linkwright::kinematics
