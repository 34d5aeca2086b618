#include "kinematics/tune/optimise_dimensions.h"

#include "kinematics/model/number_text.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

bool isLength(ParameterSlot slot) {
  return slot != ParameterSlot::FrameAngle && parameterUnit(slot) == ParameterUnit::Length;
}

// The numbers that place a ground pivot: its x and y, a four-bar's frame length and O4's
// place across the frame line.
bool placesPivot(ParameterSlot slot) {
  return slot == ParameterSlot::X || slot == ParameterSlot::Y || slot == ParameterSlot::FrameLength ||
         slot == ParameterSlot::FrameAngle;
}

std::optional<Error> markFixed(const Mechanism& m, const OptimiseConstraints& c, std::vector<OptimiseDimension>& dims) {
  std::vector<bool> fixed(m.points.size(), false);
  for (std::size_t p = 0; p < m.points.size(); ++p)
    fixed[p] = !c.fixedPivots && std::holds_alternative<GroundPoint>(m.points[p].definition);
  if (c.fixedPivots)
    for (std::size_t i = 0; i < c.fixedPivots->size(); ++i) {
      const std::string& name = (*c.fixedPivots)[i];
      const auto id = m.findPoint(name);
      if (!id || !std::holds_alternative<GroundPoint>(m.points[id->index].definition))
        return invalid("fixedPivots[" + std::to_string(i) + "]",
                       "fixedPivots[" + std::to_string(i) + "]: '" + name + "' is not a ground pivot of the linkage");
      fixed[id->index] = true;
    }
  for (OptimiseDimension& d : dims) {
    const Parameter& p = d.dimension.parameter;
    d.fixed = placesPivot(p.slot) && fixed[p.point.index] &&
              std::holds_alternative<GroundPoint>(m.points[p.point.index].definition);
  }
  return std::nullopt;
}

std::optional<Error> applyRange(const DimensionRange& r, std::size_t i, std::vector<OptimiseDimension>& dims) {
  const std::string field = "ranges[" + std::to_string(i) + "]";
  const auto d =
      std::find_if(dims.begin(), dims.end(), [&](const OptimiseDimension& x) { return x.dimension.name == r.name; });
  if (d == dims.end()) return invalid(field + ".name", field + ".name: the linkage has no dimension '" + r.name + "'");
  const std::string what = field + " (" + r.name + ")";
  if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || r.lo > r.hi)
    return invalid(field, what + " must run from a finite lo to a finite hi ≥ lo (got " + formatNumber(r.lo) + " to " +
                              formatNumber(r.hi) + ")");
  if (isLength(d->dimension.parameter.slot) && r.lo <= 0.0)
    return invalid(field, what + " is a length: its range must be positive (got " + formatNumber(r.lo) + " to " +
                              formatNumber(r.hi) + ")");
  const double v = d->dimension.value;
  if (v < r.lo || v > r.hi)
    return invalid(field, what + " must hold the start, " + formatNumber(v) + " (got " + formatNumber(r.lo) + " to " +
                              formatNumber(r.hi) + ")");
  if (d->fixed) return invalid(field, what + " places a fixed pivot: free the pivot to give it a range");
  d->lo = r.lo;
  d->hi = r.hi;
  return std::nullopt;
}

}  // namespace

Result<std::vector<OptimiseDimension>> optimiseDimensions(const Mechanism& m, const OptimiseConstraints& c) {
  if (!(c.lengthRange > 0.0 && c.lengthRange <= kMaxLengthRange))
    return invalid("lengthRange", "lengthRange must be above 0 and at most 0.95, a fraction of each length (got " +
                                      formatNumber(c.lengthRange) + ")");
  std::vector<OptimiseDimension> dims;
  double size = 0.0;
  for (const ToleranceDimension& t : toleranceDimensions(m)) {
    dims.push_back({t, t.value, t.value, false});
    if (isLength(t.parameter.slot)) size = std::max(size, std::abs(t.value));
  }
  if (auto e = markFixed(m, c, dims)) return *e;
  for (OptimiseDimension& d : dims) {
    if (d.fixed) continue;
    const double v = d.dimension.value;
    const double half = isLength(d.dimension.parameter.slot) ? c.lengthRange * v : c.lengthRange * size;
    d.lo = v - half;
    d.hi = v + half;
  }
  for (std::size_t i = 0; i < c.ranges.size(); ++i)
    if (auto e = applyRange(c.ranges[i], i, dims)) return *e;
  if (std::none_of(dims.begin(), dims.end(), [](const OptimiseDimension& d) { return !d.fixed && d.hi > d.lo; }))
    return invalid("dimensions", "nothing is left to change: every dimension is fixed or has an empty range");
  return dims;
}

Mechanism withDimensionValues(const Mechanism& start, const std::vector<OptimiseDimension>& dims,
                              const std::vector<double>& values) {
  std::vector<ToleranceDimension> tolerance;
  std::vector<double> offsets;
  tolerance.reserve(dims.size());
  offsets.reserve(dims.size());
  for (std::size_t d = 0; d < dims.size(); ++d) {
    tolerance.push_back(dims[d].dimension);
    offsets.push_back(dims[d].fixed ? 0.0 : values[d] - dims[d].dimension.value);
  }
  return offsetDimensions(start, tolerance, offsets);
}

}  // namespace linkwright::kinematics
