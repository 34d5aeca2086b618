#include "kinematics/design/coupler_atlas.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

std::optional<Error> checkAxis(const std::vector<double>& values, const std::string& name, bool ratio) {
  if (values.empty()) return Error{ErrorCode::InvalidValue, name, name + " needs at least one value"};
  if (values.size() > kMaxAtlasAxisValues)
    return Error{ErrorCode::InvalidValue, name,
                 name + " takes at most " + std::to_string(kMaxAtlasAxisValues) + " values (got " +
                     std::to_string(values.size()) + ")"};
  for (const double v : values) {
    if (ratio && !(v >= kMinAtlasRatio && v <= kMaxAtlasRatio))
      return Error{ErrorCode::InvalidValue, name,
                   name + " ratios must be between " + formatNumber(kMinAtlasRatio) + " and " +
                       formatNumber(kMaxAtlasRatio) + " crank lengths (got " + formatNumber(v) + ")"};
    if (!ratio && !(std::abs(v) <= kMaxAtlasPosition))
      return Error{ErrorCode::InvalidValue, name,
                   name + " must be finite and within ±" + formatNumber(kMaxAtlasPosition) + " coupler lengths (got " +
                       formatNumber(v) + ")"};
  }
  return std::nullopt;
}

SweepSpec gridOver(double from, double to, std::size_t samples) {
  SweepSpec spec;
  spec.fromAngle = from;
  spec.toAngle = to;
  spec.samples = samples;
  spec.omega = 1.0;  // so that a point's velocity is dP/dθ
  spec.alpha = 0.0;
  return spec;
}

// Appends the swept path of P, forwards or backwards, keeping the assembled samples.
void appendPath(const SweepResult& s, bool backwards, CouplerCurve& curve) {
  const std::size_t n = s.size(), p = fourbar::kCouplerPoint.index;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = backwards ? n - 1 - k : k;
    if (!s.assembled(j)) continue;
    curve.crankAngle.push_back(s.inputAngle[j]);
    curve.point.push_back(s.position[p][j]);
    curve.derivative.push_back(s.ok(j) ? s.velocity[p][j] : Eigen::Vector2d::Zero());
    curve.rateOk.push_back(s.ok(j) ? 1 : 0);
  }
}

SolveRequest pathRequest() {
  SolveRequest request;
  request.accelerations = false;
  request.transmissionAngles = false;
  return request;
}

Branch otherBranch(Branch b) { return b == Branch::Open ? Branch::Crossed : Branch::Open; }

// The crank angles the cell traces: a full turn, or its first range less the edge margin.
AngleRange tracedRange(const InputRange& range) {
  if (range.fullRotation) return {0.0, 2.0 * kPi};
  const AngleRange& r = range.ranges.front();
  const double margin = std::min(kAtlasEdgeMargin, 0.25 * (r.to - r.from));
  return {r.from + margin, r.to - margin};
}

}  // namespace

std::string_view toString(CrankMotion motion) {
  switch (motion) {
  case CrankMotion::FullTurn: return "full turn";
  case CrankMotion::Rocks: return "rocks";
  case CrankMotion::NeverAssembles: return "never assembles";
  }
  return "";
}

std::optional<Error> checkAtlasAxes(const AtlasAxes& axes) {
  if (auto e = checkAxis(axes.coupler, "coupler", true)) return e;
  if (auto e = checkAxis(axes.rocker, "rocker", true)) return e;
  if (auto e = checkAxis(axes.frame, "frame", true)) return e;
  if (auto e = checkAxis(axes.along, "along", false)) return e;
  if (auto e = checkAxis(axes.across, "across", false)) return e;
  if (axes.samples < kMinAtlasSamples || axes.samples > kMaxAtlasSamples)
    return Error{ErrorCode::InvalidValue, "samples",
                 "samples must be between " + std::to_string(kMinAtlasSamples) + " and " +
                     std::to_string(kMaxAtlasSamples) + " (got " + std::to_string(axes.samples) + ")"};
  return std::nullopt;
}

std::size_t atlasCellCount(const AtlasAxes& axes) {
  return axes.coupler.size() * axes.rocker.size() * axes.frame.size() * axes.along.size() * axes.across.size();
}

AtlasCellKey atlasCellKey(const AtlasAxes& axes, std::size_t index) {
  const std::size_t across = index % axes.across.size();
  index /= axes.across.size();
  const std::size_t along = index % axes.along.size();
  index /= axes.along.size();
  const std::size_t frame = index % axes.frame.size();
  index /= axes.frame.size();
  const std::size_t rocker = index % axes.rocker.size();
  index /= axes.rocker.size();
  const std::size_t coupler = index % axes.coupler.size();
  AtlasCellKey key;
  key.lengths = FourBarLengths{axes.frame[frame], 1.0, axes.coupler[coupler], axes.rocker[rocker]};
  key.point = CouplerPointSpec{axes.along[along], axes.across[across]};
  key.branch = axes.branch;
  key.samples = axes.samples;
  return key;
}

Result<Mechanism> atlasMechanism(const AtlasCellKey& key, Branch branch, double crank, const std::string& lengthUnit) {
  const FourBarLengths& l = key.lengths;
  const FourBarLengths scaled{l.frame * crank, l.crank * crank, l.coupler * crank, l.rocker * crank};
  const double c = scaled.coupler;
  return makeFourBar(scaled, branch, lengthUnit, CouplerPointSpec{key.point.along * c, key.point.across * c});
}

Result<AtlasCell> computeAtlasCell(const AtlasCellKey& key, const std::atomic<bool>* cancel) {
  const auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
  if (cancelled()) return Error{ErrorCode::Cancelled, "atlas", "the atlas was cancelled"};
  AtlasCell cell;
  cell.key = key;
  cell.grashof = classifyGrashof(key.lengths);
  const InputRange range = fourBarInputRange(key.lengths);
  if (!range.fullRotation && range.ranges.empty()) {
    cell.motion = CrankMotion::NeverAssembles;
    return cell;
  }
  cell.motion = range.fullRotation ? CrankMotion::FullTurn : CrankMotion::Rocks;
  cell.range = tracedRange(range);
  const std::size_t n = std::max<std::size_t>(key.samples, 4);
  // A full turn's last sample is one step short of the first, which closes the curve.
  const std::size_t forward = cell.motion == CrankMotion::FullTurn ? n : n / 2;
  const double to = cell.motion == CrankMotion::FullTurn
                        ? 2.0 * kPi * static_cast<double>(n - 1) / static_cast<double>(n)
                        : cell.range.to;
  SweepResult swept;
  for (const bool second : {false, true}) {
    if (second && cell.motion == CrankMotion::FullTurn) break;
    auto mechanism = atlasMechanism(key, second ? otherBranch(key.branch) : key.branch);
    if (!mechanism) return mechanism.error();
    const std::size_t count = second ? n - forward : forward;
    if (auto e = sweepInto(*mechanism, gridOver(cell.range.from, to, count), pathRequest(), swept, cancel)) return *e;
    appendPath(swept, second, cell.curve);
  }
  cell.curve.closed = true;
  if (cancelled()) return Error{ErrorCode::Cancelled, "atlas", "the atlas was cancelled"};
  cell.features = classifyCouplerCurve(cell.curve);
  return cell;
}

Result<std::vector<AtlasCell>> computeAtlasPage(const AtlasAxes& axes, std::size_t first, std::size_t count,
                                                const std::atomic<bool>* cancel) {
  if (auto e = checkAtlasAxes(axes)) return *e;
  const std::size_t total = atlasCellCount(axes);
  std::vector<AtlasCell> cells;
  for (std::size_t i = first; i < total && i - first < count; ++i) {
    auto cell = computeAtlasCell(atlasCellKey(axes, i), cancel);
    if (!cell) return cell.error();
    cells.push_back(std::move(cell).value());
  }
  return cells;
}

Result<Design> atlasCellDesign(const AtlasCellKey& key, double crank, const std::string& lengthUnit) {
  const InputRange range = fourBarInputRange(key.lengths);
  if (!range.fullRotation && range.ranges.empty())
    return Error{ErrorCode::NotAssemblable, "cell",
                 "this atlas cell's four-bar cannot be assembled at any crank angle"};
  const FourBarLengths& l = key.lengths;
  const FourBarLengths scaled{l.frame * crank, l.crank * crank, l.coupler * crank, l.rocker * crank};
  auto design = fourBarDesign(scaled, key.branch, lengthUnit,
                              CouplerPointSpec{key.point.along * scaled.coupler, key.point.across * scaled.coupler});
  if (!design || range.fullRotation) return design;
  const AngleRange traced = tracedRange(range);
  design.value().fromDeg = radToDeg(traced.from);
  design.value().toDeg = radToDeg(traced.to);
  design.value().samples = samplesEveryHalfDegree(design.value().fromDeg, design.value().toDeg);
  return design;
}

}  // namespace linkwright::kinematics
