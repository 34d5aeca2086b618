#include "kinematics/analysis/inversions.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/vec2.h"

#include <array>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// The loop order of a four-bar: frame O2O4, crank O2B, coupler BC, rocker CO4, back to the frame.
constexpr std::array<LinkRole, 4> kLoop{LinkRole::Frame, LinkRole::Crank, LinkRole::Coupler, LinkRole::Rocker};

// Ground loop link g and drive its neighbour `step` (+1 or −1) places round the loop.
FourBarLengths inverted(const std::array<double, 4>& loop, std::size_t g, int step) {
  const auto at = [&](int k) { return loop[static_cast<std::size_t>((static_cast<int>(g) + 4 + step * k) % 4)]; };
  return {at(0), at(1), at(2), at(3)};
}

Result<FourBarInversion> inversion(const std::array<double, 4>& loop, std::size_t g, Branch branch,
                                   const std::string& unit) {
  const FourBarLengths forward = inverted(loop, g, +1);
  const FourBarLengths backward = inverted(loop, g, -1);
  const GrashofReport fwd = classifyGrashof(forward);
  const GrashofReport bwd = classifyGrashof(backward);
  // Drive the neighbour that turns fully if one does, else the shorter (forward on a tie, so
  // grounding the frame gives back the original four-bar).
  const bool useForward = fwd.inputFullyRotates || (!bwd.inputFullyRotates && forward.crank <= backward.crank);
  FourBarInversion inv;
  inv.grounded = kLoop[g];
  inv.driven = kLoop[(g + (useForward ? 1 : 3)) % 4];
  inv.lengths = useForward ? forward : backward;
  inv.grashof = useForward ? fwd : bwd;
  inv.name = std::string(textbookName(inv.grashof.category));
  auto mechanism = makeFourBar(inv.lengths, branch, unit);
  if (!mechanism) return mechanism.error();
  inv.mechanism = std::move(mechanism).value();
  return inv;
}

Mechanism sliderCrankFromCrankGround(double a, double b, const std::string& unit) {
  Mechanism m;
  m.lengthUnit = unit;
  // The old frame is a slotted guide about O2 through the block at C; its tip G is drawn a
  // rod-and-crank length out, past C at every angle.
  m.points = {{"B", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
              {"O2", GroundPoint{Eigen::Vector2d(-a, 0.0)}},
              {"C", CrankPoint{PointId{0}, b, 0.0}},
              {"G", RprPoint{PointId{1}, PointId{2}, a + b}}};
  m.links = {{"rod", PointId{0}, PointId{2}}, {"guide", PointId{1}, PointId{3}}};
  return m;
}

Mechanism sliderCrankFromRodGround(double a, double b, const std::string& unit) {
  Mechanism m;
  m.lengthUnit = unit;
  // The block at C is the cylinder, turning about C; the old frame slides in it, pinned at O2.
  m.points = {{"B", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
              {"C", GroundPoint{Eigen::Vector2d(b, 0.0)}},
              {"O2", CrankPoint{PointId{0}, a, 0.0}},
              {"G", RprPoint{PointId{1}, PointId{2}, a + b}}};
  m.links = {{"crank", PointId{0}, PointId{2}}, {"cylinder", PointId{1}, PointId{3}}};
  return m;
}

Mechanism sliderCrankFromSliderGround(double a, double b, double e, const std::string& unit) {
  Mechanism m;
  m.lengthUnit = unit;
  // The old frame's pivot O2 runs on the line through it parallel to the fixed guide, e
  // below C, at the crank's length from B: a slider-crank with the rod as its crank.
  m.points = {{"C", GroundPoint{Eigen::Vector2d(0.0, 0.0)}},
              {"B", CrankPoint{PointId{0}, b, 0.0}},
              {"O2", RrpPoint{PointId{1}, a, Guide{std::nullopt, Eigen::Vector2d(0.0, -e), 0.0}, Branch::Crossed}}};
  m.links = {{"rod", PointId{0}, PointId{1}}, {"crank", PointId{1}, PointId{2}}};
  return m;
}

}  // namespace

std::string_view textbookName(GrashofClass category) {
  switch (category) {
  case GrashofClass::CrankRocker: return "crank-rocker";
  case GrashofClass::DoubleCrank: return "double-crank (drag link)";
  case GrashofClass::DoubleRocker: return "double-rocker (Grashof)";
  case GrashofClass::ChangePoint: return "change point";
  case GrashofClass::TripleRocker: return "triple-rocker (non-Grashof)";
  }
  return "unknown";
}

Result<std::vector<FourBarInversion>> fourBarInversions(const FourBarLengths& lengths, Branch branch,
                                                        const std::string& lengthUnit) {
  if (auto e = checkFourBarLengths(lengths)) return *e;
  const std::array<double, 4> loop{lengths.frame, lengths.crank, lengths.coupler, lengths.rocker};
  std::vector<FourBarInversion> out;
  for (std::size_t g = 0; g < 4; ++g) {
    auto inv = inversion(loop, g, branch, lengthUnit);
    if (!inv) return inv.error();
    out.push_back(std::move(inv).value());
  }
  return out;
}

std::string_view toString(SliderCrankLink link) {
  switch (link) {
  case SliderCrankLink::Frame: return "frame (guide)";
  case SliderCrankLink::Crank: return "crank";
  case SliderCrankLink::Rod: return "rod";
  case SliderCrankLink::Slider: return "slider";
  }
  return "unknown";
}

std::optional<SliderCrankGeometry> sliderCrankGeometry(const Mechanism& m, const SliderCrankStructure& s) {
  const auto& crank = std::get<CrankPoint>(m.points[s.b.index].definition);
  const auto& slider = std::get<RrpPoint>(m.points[s.c.index].definition);
  const auto* o2 = std::get_if<GroundPoint>(&m.points[s.o2.index].definition);
  if (!o2) return std::nullopt;
  const Eigen::Vector2d u(std::cos(s.guideAngle), std::sin(s.guideAngle));
  return SliderCrankGeometry{crank.length, slider.length, cross(u, slider.guide.point - o2->position), false};
}

Result<std::vector<SliderCrankInversion>> sliderCrankInversions(const SliderCrankGeometry& g, const std::string& unit) {
  if (auto e = checkSliderCrank(g)) return *e;
  const double a = g.crank, b = g.rod, e = g.offset;
  // a = b puts C on O2 once a turn: the slot's direction is undetermined there.
  const bool equal = std::abs(a - b) <= 1e-12 * std::max(a, b);
  const bool offset = e != 0.0;
  const std::string why = "the guide is offset " + kinematics::formatShort(e) + " " + unit +
                          " from O2, and a slotted link's slot passes through its pivot in this model";
  std::vector<SliderCrankInversion> out(4);
  out[0] = {SliderCrankLink::Frame, "slider-crank", "crank", a + std::abs(e) <= b, false, std::nullopt, {}};
  auto first = makeSliderCrank(g, Branch::Open, unit);
  if (!first) return first.error();
  out[0].mechanism = std::move(first).value();
  out[1] = {SliderCrankLink::Crank,
            a < b ? "Whitworth quick return (rotating guide)" : "crank-shaper (oscillating guide)",
            "rod",
            !equal,
            a < b,
            std::nullopt,
            offset ? why : std::string()};
  out[2] = {SliderCrankLink::Rod,
            a < b ? "oscillating cylinder" : "rotating cylinder",
            "crank",
            !equal,
            a > b,
            std::nullopt,
            offset ? why : std::string()};
  out[3] = {SliderCrankLink::Slider,
            "fixed piston (pendulum pump)",
            "rod",
            b + std::abs(e) <= a,
            false,
            sliderCrankFromSliderGround(a, b, e, unit),
            {}};
  if (!offset && !equal) {
    out[1].mechanism = sliderCrankFromCrankGround(a, b, unit);
    out[2].mechanism = sliderCrankFromRodGround(a, b, unit);
  } else if (!offset) {
    out[1].note = out[2].note = "crank and rod are equal, so C passes through O2 and the slot's direction is lost";
  }
  for (const auto& inv : out)
    if (inv.mechanism)
      if (auto err = checkMechanism(*inv.mechanism)) return *err;
  return out;
}

}  // namespace linkwright::kinematics

namespace linkwright::kinematics {

Result<LinkageInversions> linkageInversions(const Mechanism& m, const std::string& source, const std::string& kind) {
  LinkageInversions out;
  if (const auto f = asFourBar(m, PointsOnLinks::AnyLink)) {
    auto all = fourBarInversions(f->lengths, f->branch, m.lengthUnit);
    if (!all) return all.error();
    out.fourBar = f->lengths;
    out.fourBars = std::move(*all);
    return out;
  }
  if (const auto s = asSliderCrank(m, PointsOnLinks::AnyLink))
    if (const auto g = sliderCrankGeometry(m, *s)) {
      auto all = sliderCrankInversions(*g, m.lengthUnit);
      if (!all) return all.error();
      out.sliderCrank = *g;
      out.sliderCranks = std::move(*all);
      return out;
    }
  const std::string what = kind.empty() ? "neither" : "a " + kind;
  // A linkage driven along a path or by an actuator may be a slider-crank (piston-driven is),
  // but the inversions are built from its crank, which it does not have as its input.
  if (inputKind(m) != InputKind::Angle)
    return Error{ErrorCode::InvalidStructure, "mechanism",
                 "inversions needs a four-bar or a slider-crank driven by its crank; " + source + " is " + what +
                     " driven by its " + inputName(m) + ", a length, so it has no crank to build the inversions from"};
  return Error{ErrorCode::InvalidStructure, "mechanism",
               "inversions needs a four-bar or a slider-crank (" + source + " is " + what + ")"};
}

}  // namespace linkwright::kinematics
