#include "kinematics/synthesis/swing_crank_rocker.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/golden_section.h"
#include "kinematics/synthesis/defects.h"
#include "kinematics/synthesis/message_text.h"
#include "kinematics/synthesis/time_ratio.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// `x` (> 0) to three significant digits, rounded up or down.
double threeDigits(double x, bool up) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2.0);
  return (up ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
}

// Grid for locating the crank-rocker ranges and for bracketing the best candidate; bisection
// then pins each range's ends to round-off.
constexpr int kScan = 512;
constexpr int kBisections = 200;

// The construction for a unit rocker, in the frame of the header: C1 = (−s, 0), C2 = (s, 0),
// O4 on the bisector above the chord.
struct Construction {
  Eigen::Vector2d c1, c2, o4;
  double s = 0.0;
  double alpha = 0.0;
};

Construction construction(const SwingTarget& t) {
  Construction g;
  g.s = std::sin(t.swing / 2.0);
  g.c1 = {-g.s, 0.0};
  g.c2 = {g.s, 0.0};
  g.o4 = {0.0, std::cos(t.swing / 2.0)};
  g.alpha = timeRatioAngle(t.timeRatio);
  return g;
}

// O2 at family point p, or nullopt if p is off the family's curves.
std::optional<Eigen::Vector2d> pivotAt(const Construction& g, double p) {
  const double q = std::abs(p);
  if (!(q > 0.0 && q < 1.0)) return std::nullopt;
  const double r1 = 2.0 * g.s * q / (1.0 - q);
  if (g.alpha == 0.0) return Eigen::Vector2d(-g.s - r1, 0.0);
  // Below the chord: centre (0, −s·cot α), radius s / sin α; C1 at angle π/2 + α from the
  // centre, the C1 half running on to the bisector at 3π/2 (a chord from C1 of 2R·cos(α/2)).
  const double radius = g.s / std::sin(g.alpha);
  if (r1 >= 2.0 * radius * std::cos(g.alpha / 2.0)) return std::nullopt;
  const double at = kPi / 2.0 + g.alpha + 2.0 * std::asin(r1 / (2.0 * radius));
  Eigen::Vector2d o2(radius * std::cos(at), -g.s * std::cos(g.alpha) / std::sin(g.alpha) + radius * std::sin(at));
  if (p > 0.0) o2.y() = -o2.y();
  return o2;
}

// The unit-rocker four-bar for pivot o2, if it is a crank-rocker whose limits are C1 and C2.
struct Built {
  FourBarLengths lengths;
  Branch branch = Branch::Open;
};

std::optional<Built> buildAt(const Construction& g, const Eigen::Vector2d& o2) {
  const double r1 = (g.c1 - o2).norm(), r2 = (g.c2 - o2).norm();
  const Eigen::Vector2d frame = g.o4 - o2;
  const FourBarLengths l{frame.norm(), (r2 - r1) / 2.0, (r2 + r1) / 2.0, 1.0};
  const double scale = l.frame + l.coupler + 1.0;
  if (!(l.crank > 1e-12 * scale)) return std::nullopt;
  // C1 and C2 strictly on one side of the frame line: one assembly branch reaches both.
  const double side1 = cross(frame, g.c1 - o2), side2 = cross(frame, g.c2 - o2);
  const double slack = 1e-12 * scale * scale;
  if (!((side1 > slack && side2 > slack) || (side1 < -slack && side2 < -slack))) return std::nullopt;
  const GrashofReport grashof = classifyGrashof(l);
  if (grashof.category != GrashofClass::CrankRocker || !grashof.inputFullyRotates || grashof.outputFullyRotates)
    return std::nullopt;
  return Built{l, side2 > 0.0 ? Branch::Open : Branch::Crossed};
}

std::optional<Built> builtAt(const Construction& g, double p) {
  const auto o2 = pivotAt(g, p);
  return o2 ? buildAt(g, *o2) : std::nullopt;
}

// The worst transmission angle at p (the objective): −1 off the crank-rocker ranges, and,
// when `bounded`, −1 where the link lengths break the bounds (scale-free: the ratio only).
double objective(const Construction& g, double p, const DefectBounds* bounded) {
  const auto b = builtAt(g, p);
  if (!b) return -1.0;
  const FourBarLengths& l = b->lengths;
  if (bounded && bounded->maxLinkRatio) {
    const double longest = std::max({l.frame, l.crank, l.coupler, l.rocker});
    const double shortest = std::min({l.frame, l.crank, l.coupler, l.rocker});
    if (longest > *bounded->maxLinkRatio * shortest) return -1.0;
  }
  return worstTransmission(l).value_or(-1.0);
}

// The family point with the largest objective: a fine grid brackets it, golden section
// refines it. Returns nullopt if no grid point scores.
std::optional<double> bestParameter(const Construction& g, const std::vector<ParameterRange>& valid,
                                    const DefectBounds* bounded) {
  double bestP = 0.0, bestValue = -1.0;
  const ParameterRange* bestRange = nullptr;
  for (const ParameterRange& r : valid)
    for (int k = 1; k < kScan; ++k) {
      const double p = r.from + (r.to - r.from) * k / kScan;
      const double value = objective(g, p, bounded);
      if (value > bestValue) {
        bestValue = value;
        bestP = p;
        bestRange = &r;
      }
    }
  if (!bestRange) return std::nullopt;
  const double step = (bestRange->to - bestRange->from) / kScan;
  const double lo = std::max(bestRange->from, bestP - step), hi = std::min(bestRange->to, bestP + step);
  const auto [p, value] =
      goldenSectionMaximum([&](double x) { return objective(g, x, bounded); }, lo, hi, 1e-15).best();
  return value >= bestValue ? p : bestP;
}

// The last valid point between a valid `in` and an invalid `out`.
double edge(const Construction& g, double in, double out) {
  for (int k = 0; k < kBisections; ++k) {
    const double mid = 0.5 * (in + out);
    if (mid == in || mid == out) break;
    (builtAt(g, mid) ? in : out) = mid;
  }
  return in;
}

std::vector<ParameterRange> ranges(const Construction& g) {
  std::vector<ParameterRange> out;
  // When Q = 1 both curves are the same line: one side suffices.
  const std::vector<double> sides = g.alpha == 0.0 ? std::vector<double>{1.0} : std::vector<double>{-1.0, 1.0};
  for (const double sign : sides) {
    std::optional<double> start;
    for (int k = 0; k <= kScan; ++k) {
      const double p = sign * k / kScan;
      const bool valid = k > 0 && k < kScan && builtAt(g, p).has_value();
      const double previous = sign * (k - 1) / kScan;
      if (valid && !start) start = k == 1 ? edge(g, p, 0.0) : edge(g, p, previous);
      if (!valid && start) {
        const double end = edge(g, previous, p);
        out.push_back({std::min(*start, end), std::max(*start, end)});
        start.reset();
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const ParameterRange& a, const ParameterRange& b) { return a.from < b.from; });
  return out;
}

Result<CrankRockerCandidate> candidateAt(const SwingTarget& t, const Construction& g, double p,
                                         const DefectBounds& bounds) {
  const auto o2 = pivotAt(g, p);
  const auto built = o2 ? buildAt(g, *o2) : std::nullopt;
  if (!built)
    return Error{ErrorCode::InvalidValue, "parameter",
                 "parameter " + formatNumber(p) + " does not give a crank-rocker for this swing and time ratio"};
  CrankRockerCandidate c;
  c.parameter = p;
  c.branch = built->branch;
  const double k = t.scale == SwingScale::Rocker ? t.length : t.length / built->lengths.frame;
  c.lengths = {k * built->lengths.frame, k * built->lengths.crank, k * built->lengths.coupler, k};
  // Angles in the design's frame: O2 at the origin, O4 along +x.
  const Eigen::Vector2d frame = g.o4 - *o2;
  const double tilt = std::atan2(frame.y(), frame.x());
  const auto angleOf = [&](const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()) - tilt; };
  c.extendedCrankAngle = wrapPositive(angleOf(g.c2 - *o2));
  c.foldedCrankAngle = wrapPositive(angleOf(g.c1 - *o2) + kPi);
  c.extendedRockerAngle = wrapAngle(angleOf(g.c2 - g.o4));
  c.foldedRockerAngle = wrapAngle(angleOf(g.c1 - g.o4));
  auto design = fourBarDesign(c.lengths, c.branch, t.lengthUnit);
  if (!design) {
    // Every length scales with the one given: say which range of it builds this member.
    const auto [shortest, longest] =
        std::minmax({c.lengths.frame, c.lengths.crank, c.lengths.coupler, c.lengths.rocker});
    // Rounded inwards, so that both ends do build.
    const double from = threeDigits(t.length * kMinLength / shortest, true);
    const double to = threeDigits(t.length * kMaxLength / longest, false);
    const std::string given = t.scale == SwingScale::Rocker ? "rocker" : "frame";
    Error e = design.error();
    e.field = "length";
    e.message = "the crank-rocker at parameter " + formatNumber(p) + " cannot be built: " + e.message;
    if (from <= to)
      e.message += "; it can with a " + given + " length between " + kinematics::formatShort(from, 3) + " and " +
                   kinematics::formatShort(to, 3) + " " + t.lengthUnit;
    return e;
  }
  const FourBarCheck check = checkFourBar(
      {c.lengths, {c.extendedCrankAngle, c.foldedCrankAngle}, {c.branch, c.branch}, true, std::nullopt}, bounds);
  c.candidate = {std::move(*design), 0.0, check.grashof, check.minTransmission, check.defects};
  return c;
}

}  // namespace

std::optional<Error> checkSwingTarget(const SwingTarget& t) {
  if (!(std::isfinite(t.swing) && t.swing > 0.0 && t.swing < kPi))
    return Error{ErrorCode::InvalidValue, "swing",
                 "swing must be between 0° and 180°, both excluded (got " + synthesis_text::degrees(t.swing) + ")"};
  if (auto e = checkTimeRatio(t.timeRatio)) return e;
  return checkLength(t.length, "length", t.scale == SwingScale::Rocker ? "(the rocker's)" : "(the frame's)");
}

Result<std::vector<ParameterRange>> crankRockerRanges(const SwingTarget& t) {
  if (auto e = checkSwingTarget(t)) return *e;
  return ranges(construction(t));
}

Result<CrankRockerCandidate> crankRockerAt(const SwingTarget& t, double parameter, const DefectBounds& bounds) {
  if (auto e = checkSwingTarget(t)) return *e;
  if (!std::isfinite(parameter))
    return Error{ErrorCode::InvalidValue, "parameter",
                 "parameter must be finite, in (-1, 1) (got " + formatNumber(parameter) + ")"};
  return candidateAt(t, construction(t), parameter, bounds);
}

Result<SwingSynthesis> synthesiseCrankRocker(const SwingTarget& t, std::size_t count, const DefectBounds& bounds) {
  if (auto e = checkSwingTarget(t)) return *e;
  if (count < 1 || count > 100000)
    return Error{ErrorCode::InvalidValue, "count",
                 "count must be between 1 and 100000 (got " + std::to_string(count) + ")"};
  const Construction g = construction(t);
  SwingSynthesis out;
  out.valid = ranges(g);
  if (out.valid.empty())
    return Error{ErrorCode::InvalidValue, "swing", "no crank-rocker has this swing and time ratio"};
  double total = 0.0;
  for (const ParameterRange& r : out.valid) total += r.to - r.from;
  // The family, spread over the ranges in proportion to their lengths; a point whose
  // linkage cannot be built (a length ratio past the input domain) is left out.
  for (const ParameterRange& r : out.valid) {
    const auto n = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::lround(static_cast<double>(count) * (r.to - r.from) / total)));
    for (std::size_t k = 0; k < n; ++k)
      if (auto c = candidateAt(t, g, r.from + (r.to - r.from) * (static_cast<double>(k) + 0.5) / static_cast<double>(n),
                               bounds))
        out.family.push_back(std::move(*c));
  }
  // The best within the link-length bounds; if nothing meets them, the best regardless.
  auto p = bestParameter(g, out.valid, &bounds);
  if (!p) p = bestParameter(g, out.valid, nullptr);
  if (!p) return Error{ErrorCode::InvalidValue, "swing", "no crank-rocker has this swing and time ratio"};
  auto best = candidateAt(t, g, *p, bounds);
  if (!best) return best.error();
  out.best = std::move(*best);
  return out;
}

}  // namespace linkwright::kinematics
