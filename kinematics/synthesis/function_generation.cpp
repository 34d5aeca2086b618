#include "kinematics/synthesis/function_generation.h"

#include "kinematics/model/number_text.h"
#include "kinematics/synthesis/named_function.h"

#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/golden_section.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/synthesis/defects.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

std::optional<Error> checkFinite(double value, const std::string& field) {
  if (std::isfinite(value)) return std::nullopt;
  return invalid(field, field + " must be finite (got " + formatNumber(value) + ")");
}

std::optional<Error> checkSpan(double span, const std::string& field) {
  if (std::isfinite(span) && span != 0.0 && std::abs(span) < 2.0 * kPi) return std::nullopt;
  return invalid(field, field + " must be nonzero and less than a turn in size (got " + formatNumber(span) + " rad)");
}

// f(x), or the error naming the function and x.
Result<double> evaluate(const FunctionTarget& t, double x) {
  const double y = t.f(x);
  if (!std::isfinite(y))
    return invalid("function",
                   "function must be finite on [x0, x1] (got " + formatNumber(y) + " at x = " + formatNumber(x) + ")");
  return y;
}

std::optional<Error> checkTarget(const FunctionTarget& t, const FunctionOptions& o) {
  if (!t.f) return invalid("function", "function must be given");
  if (auto e = checkFinite(t.x0, "x0")) return e;
  if (auto e = checkFinite(t.x1, "x1")) return e;
  if (!(t.x1 > t.x0))
    return invalid("x1",
                   "x1 must be greater than x0 (got x0 = " + formatNumber(t.x0) + ", x1 = " + formatNumber(t.x1) + ")");
  if (auto e = checkFinite(t.inputStart, "inputStart")) return e;
  if (auto e = checkFinite(t.outputStart, "outputStart")) return e;
  if (auto e = checkSpan(t.inputSpan, "inputSpan")) return e;
  if (auto e = checkSpan(t.outputSpan, "outputSpan")) return e;
  if (auto e = checkLength(t.frame, "frame")) return e;
  if (o.points.empty() && (o.count < 3 || o.count > 1000))
    return invalid("count", "count must be between 3 and 1000 (got " + std::to_string(o.count) + ")");
  if (!o.points.empty() && o.points.size() < 3)
    return invalid("points", "points must number at least 3 (got " + std::to_string(o.points.size()) + ")");
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const std::string field = "points[" + std::to_string(i) + "]";
    const double x = o.points[i];
    if (!(std::isfinite(x) && x >= t.x0 && x <= t.x1))
      return invalid(field, field + " must lie in [x0, x1] = [" + formatNumber(t.x0) + ", " + formatNumber(t.x1) +
                                "] (got " + formatNumber(x) + ")");
    if (i > 0 && !(x > o.points[i - 1]))
      return invalid(field, field + " must be greater than the point before it (got " + formatNumber(x) + " after " +
                                formatNumber(o.points[i - 1]) + "): precision points must be distinct and increasing");
  }
  if (o.samples < 2 || o.samples > 1000000)
    return invalid("samples", "samples must be between 2 and 1000000 (got " + std::to_string(o.samples) + ")");
  return std::nullopt;
}

// The linear maps of the header.
struct Maps {
  const FunctionTarget* t = nullptr;
  double y0 = 0.0, y1 = 1.0;
  double input(double x) const { return t->inputStart + t->inputSpan * (x - t->x0) / (t->x1 - t->x0); }
  double output(double y) const { return t->outputStart + t->outputSpan * (y - y0) / (y1 - y0); }
};

// The branch of the four-bar with signed crank a and rocker c through the pair (θ2, θ4).
Branch branchAt(const FreudensteinLinkage& l, const AnglePair& p) {
  const double a = l.crankReversed ? -l.lengths.crank : l.lengths.crank;
  const double c = l.rockerReversed ? -l.lengths.rocker : l.lengths.rocker;
  const Eigen::Vector2d o4(l.lengths.frame, 0.0);
  const Eigen::Vector2d b = a * Eigen::Vector2d(std::cos(p.input), std::sin(p.input));
  const Eigen::Vector2d cPoint = o4 + c * Eigen::Vector2d(std::cos(p.output), std::sin(p.output));
  return cross(cPoint - b, cPoint - o4) >= 0.0 ? Branch::Open : Branch::Crossed;
}

// The output error at x (rad), solving the built linkage; nullopt where it cannot be assembled.
std::optional<double> outputError(const Mechanism& m, const Maps& maps, double outputOffset, double x) {
  const auto y = maps.t->f(x);
  if (!std::isfinite(y)) return std::nullopt;
  SolveRequest request{false, false};
  request.transmissionAngles = false;
  const auto pose = solvePose(m, {maps.input(x), 0.0, 0.0}, request);
  if (!pose) return std::nullopt;
  return wrapAngle(pose->linkAngle[fourbar::kRocker.index] - outputOffset - maps.output(y));
}

StructuralError structuralError(const Mechanism& m, const Maps& maps, double outputOffset, std::size_t samples) {
  const FunctionTarget& t = *maps.t;
  StructuralError e;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double x =
        i + 1 == samples ? t.x1 : t.x0 + (t.x1 - t.x0) * static_cast<double>(i) / static_cast<double>(samples - 1);
    const auto err = outputError(m, maps, outputOffset, x);
    if (!err) {
      e.notAssembled.push_back(x);
      continue;
    }
    e.x.push_back(x);
    e.outputError.push_back(*err);
    if (std::abs(*err) >= e.maxAbs) {
      e.maxAbs = std::abs(*err);
      e.maxAt = x;
      peak = e.x.size() - 1;
    }
  }
  if (e.x.empty()) return e;
  // Refine the peak between its neighbouring samples.
  const double lo = peak > 0 ? e.x[peak - 1] : e.x[peak];
  const double hi = peak + 1 < e.x.size() ? e.x[peak + 1] : e.x[peak];
  if (hi > lo) {
    const auto size = [&](double x) {
      const auto err = outputError(m, maps, outputOffset, x);
      return err ? std::abs(*err) : -1.0;
    };
    const auto [x, value] = goldenSectionMaximum(size, lo, hi, 1e-13 * (t.x1 - t.x0)).best();
    if (value > e.maxAbs) {
      e.maxAbs = value;
      e.maxAt = x;
    }
  }
  e.maxAbsY = e.maxAbs * std::abs(maps.y1 - maps.y0) / std::abs(t.outputSpan);
  return e;
}

Design functionDesign(Mechanism m, const FunctionTarget& t) {
  Design d;
  d.kind = "four-bar";
  d.mechanism = std::move(m);
  d.fromDeg = radToDeg(std::min(t.inputStart, t.inputStart + t.inputSpan));
  d.toDeg = radToDeg(std::max(t.inputStart, t.inputStart + t.inputSpan));
  d.samples = std::max<std::size_t>(2, samplesEveryHalfDegree(d.fromDeg, d.toDeg));
  return d;
}

}  // namespace

std::vector<double> chebyshevSpacing(double x0, double x1, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j)
    x[j] = 0.5 * (x0 + x1) -
           0.5 * (x1 - x0) * std::cos((2.0 * static_cast<double>(j) + 1.0) * kPi / (2.0 * static_cast<double>(n)));
  return x;
}

Result<FunctionSynthesis> synthesiseFunction(const FunctionTarget& t, const FunctionOptions& o,
                                             const DefectBounds& bounds) {
  if (auto e = checkTarget(t, o)) return *e;
  Maps maps{&t};
  const auto y0 = evaluate(t, t.x0), y1 = evaluate(t, t.x1);
  if (!y0) return y0.error();
  if (!y1) return y1.error();
  if (*y0 == *y1)
    return invalid("function", "function must differ at x0 and x1 (both give " + formatNumber(*y0) +
                                   "): the output range cannot be mapped");
  maps.y0 = *y0;
  maps.y1 = *y1;

  FunctionSynthesis s;
  s.points = o.points.empty() ? chebyshevSpacing(t.x0, t.x1, o.count) : o.points;
  for (const double x : s.points) {
    const auto y = evaluate(t, x);
    if (!y) return y.error();
    s.precisionAngles.push_back({maps.input(x), maps.output(*y)});
  }
  auto k = freudensteinCoefficients(s.precisionAngles);
  if (!k) return k.error();
  s.k = *k;
  auto linkage = freudensteinLinkage(s.k, t.frame);
  if (!linkage) return linkage.error();
  s.linkage = *linkage;
  s.branch = branchAt(s.linkage, s.precisionAngles.front());
  s.outputOffset = s.linkage.rockerReversed ? kPi : 0.0;
  auto m = makeFourBar(s.linkage.lengths, s.branch, t.lengthUnit);
  if (!m) return m.error();
  const double phase = s.linkage.crankReversed ? kPi : 0.0;
  std::get<CrankPoint>(m.value().points[fourbar::kB.index].definition).phase = phase;
  s.error = structuralError(*m, maps, s.outputOffset, o.samples);

  FourBarTask task{
      s.linkage.lengths, {}, {}, false, CrankSpan{t.inputStart + phase, t.inputStart + t.inputSpan + phase}};
  for (const AnglePair& p : s.precisionAngles) {
    task.crankAngles.push_back(p.input + phase);
    task.branches.push_back(branchAt(s.linkage, p));
  }
  FourBarCheck check = checkFourBar(task, bounds);
  s.candidate = {functionDesign(std::move(m).value(), t), s.error.maxAbs, check.grashof, check.minTransmission,
                 std::move(check.defects)};
  return s;
}

Result<FunctionSynthesis> synthesiseFunction(const FunctionSpec& spec, const std::string& lengthUnit,
                                             const DefectBounds& bounds) {
  const NamedFunction* f = findNamedFunction(spec.function);
  if (f == nullptr) {
    std::string names;
    for (const NamedFunction& g : namedFunctions()) names += (names.empty() ? "" : ", ") + std::string(g.name);
    return Error{ErrorCode::InvalidValue, "function",
                 "function must be one of " + names + " (got \"" + spec.function + "\")"};
  }
  if (spec.x1 > spec.x0)
    if (auto e = checkFunctionRange(*f, spec.x0, spec.x1)) return *e;
  const FunctionTarget target{f->f,           spec.x0,          spec.x1,         spec.inputStart,
                              spec.inputSpan, spec.outputStart, spec.outputSpan, spec.frame,
                              lengthUnit};
  FunctionOptions options;
  options.points = spec.points;
  options.count = spec.count;
  return synthesiseFunction(target, options, bounds);
}

}  // namespace linkwright::kinematics
