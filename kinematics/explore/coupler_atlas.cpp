#include "kinematics/explore/coupler_atlas.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <array>
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

SolveRequest pathRequest() {
  SolveRequest request;
  request.accelerations = false;
  request.transmissionAngles = false;
  return request;
}

Branch otherBranch(Branch b) { return b == Branch::Open ? Branch::Crossed : Branch::Open; }

// A full turn's curve: P at n angles 2πk/n (the last one step short of closing), each pose solved
// alone on the cell's branch. For a turning crank that is the sweep's path; a change-point
// linkage's sweep would carry on through its flat position into the other branch, and its curve
// would not close in one turn (a jump at the turn's end, found as a straight run), on a side that
// depends on whether a sample falls on the flat position: the branch held is one closed curve.
std::optional<Error> fullTurnPath(const AtlasCellKey& key, std::size_t n, CouplerCurve& curve,
                                  const std::atomic<bool>* cancel) {
  auto mechanism = atlasMechanism(key, key.branch);
  if (!mechanism) return mechanism.error();
  Pose pose;
  preparePose(*mechanism, pose);
  const SweepSpec grid = gridOver(0.0, 2.0 * kPi * static_cast<double>(n - 1) / static_cast<double>(n), n);
  const std::size_t p = fourbar::kCouplerPoint.index;
  for (std::size_t k = 0; k < n; ++k) {
    if (cancel && cancel->load(std::memory_order_relaxed))
      return Error{ErrorCode::Cancelled, "atlas", "the atlas was cancelled"};
    const double theta = sweepAngle(grid, k);
    const PoseReport report = solvePoseInto(*mechanism, sweepDriver(grid, k), pathRequest(), pose);
    if (report.status == PoseStatus::NotAssemblable) continue;
    const bool ok = report.status == PoseStatus::Ok;
    curve.parameter.push_back(theta);
    curve.crankAngle.push_back(theta);
    curve.point.push_back(pose.position[p]);
    curve.derivative.push_back(ok ? pose.velocity[p] : Eigen::Vector2d::Zero());
    curve.rateOk.push_back(ok ? 1 : 0);
  }
  return std::nullopt;
}

// A rocking crank's curve: θ = c − r cos u at u = 2π(k + ½)/n, the cell's branch for u < π and
// the other for u > π, each pose solved alone on its branch (no toggle lies between two of one
// branch's samples, so it is the sweep's path); dP/du = dP/dθ · r sin u.
std::optional<Error> rockingPath(const AtlasCellKey& key, const AngleRange& range, std::size_t n, CouplerCurve& curve,
                                 const std::atomic<bool>* cancel) {
  const double c = 0.5 * (range.from + range.to), r = 0.5 * (range.to - range.from);
  std::array<Mechanism, 2> mechanisms;
  std::array<Pose, 2> poses;
  for (std::size_t b = 0; b < 2; ++b) {
    auto m = atlasMechanism(key, b == 0 ? key.branch : otherBranch(key.branch));
    if (!m) return m.error();
    mechanisms[b] = std::move(m).value();
    preparePose(mechanisms[b], poses[b]);
  }
  const std::size_t p = fourbar::kCouplerPoint.index;
  for (std::size_t k = 0; k < n; ++k) {
    if (cancel && cancel->load(std::memory_order_relaxed))
      return Error{ErrorCode::Cancelled, "atlas", "the atlas was cancelled"};
    const double u = rockingParameter(k, n);
    const std::size_t b = u < kPi ? 0 : 1;
    const double theta = c - r * std::cos(u);
    const PoseReport report = solvePoseInto(mechanisms[b], {theta, 1.0, 0.0}, pathRequest(), poses[b]);
    if (report.status == PoseStatus::NotAssemblable) continue;
    const bool ok = report.status == PoseStatus::Ok;
    curve.parameter.push_back(u);
    curve.crankAngle.push_back(theta);
    curve.point.push_back(poses[b].position[p]);
    curve.derivative.push_back(ok ? Eigen::Vector2d(poses[b].velocity[p] * r * std::sin(u)) : Eigen::Vector2d::Zero());
    curve.rateOk.push_back(ok ? 1 : 0);
  }
  return std::nullopt;
}

// The crank angles the cell traces: a full turn, or its first range less the edge margin.
AngleRange tracedRange(const InputRange& range) {
  if (range.fullRotation) return {0.0, 2.0 * kPi};
  const AngleRange& r = range.ranges.front();
  const double margin = std::min(kAtlasEdgeMargin, 0.25 * (r.to - r.from));
  return {r.from + margin, r.to - margin};
}

}  // namespace

double rockingParameter(std::size_t k, std::size_t samples) {
  return 2.0 * kPi * (static_cast<double>(k) + 0.5) / static_cast<double>(samples);
}

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
  cell.range = range.fullRotation ? AngleRange{0.0, 2.0 * kPi} : range.ranges.front();
  const std::size_t n = std::max<std::size_t>(key.samples, 4);
  const auto failed = cell.motion == CrankMotion::FullTurn ? fullTurnPath(key, n, cell.curve, cancel)
                                                           : rockingPath(key, cell.range, n, cell.curve, cancel);
  if (failed) return *failed;
  cell.curve.closed = true;
  if (cancelled()) return Error{ErrorCode::Cancelled, "atlas", "the atlas was cancelled"};
  cell.features = classifyCouplerCurve(cell.curve);
  return cell;
}

Result<std::size_t> runAtlas(const AtlasAxes& axes, std::size_t first, std::size_t count, const AtlasCellVisitor& visit,
                             const RunControl& control) {
  if (auto e = checkAtlasAxes(axes)) return *e;
  const std::size_t total = atlasCellCount(axes);
  const std::size_t cells = first < total ? std::min(count, total - first) : 0;
  if (cells > kMaxAtlasRunCells)
    return Error{ErrorCode::InvalidValue, "count",
                 "an atlas run computes at most " + std::to_string(kMaxAtlasRunCells) + " cells (asked " +
                     std::to_string(cells) + ")"};
  for (std::size_t k = 0; k < cells; ++k) {
    if (control.cancelled()) return cancelledError();
    auto cell = computeAtlasCell(atlasCellKey(axes, first + k), control.cancel);
    if (!cell) return cell.error();
    if (!visit(first + k, *cell)) return k + 1;
    if (control.progress) control.progress(k + 1, cells);
  }
  return cells;
}

Result<std::vector<AtlasCell>> computeAtlasPage(const AtlasAxes& axes, std::size_t first, std::size_t count,
                                                const std::atomic<bool>* cancel) {
  std::vector<AtlasCell> cells;
  auto run = runAtlas(
      axes, first, count,
      [&](std::size_t, const AtlasCell& cell) {
        cells.push_back(cell);
        return true;
      },
      RunControl{cancel, {}});
  if (!run) return run.error();
  return cells;
}

Result<Design> atlasCellDesign(const AtlasCellKey& key, double crank, const std::string& lengthUnit, double omega) {
  const InputRange range = fourBarInputRange(key.lengths);
  if (!range.fullRotation && range.ranges.empty())
    return Error{ErrorCode::NotAssemblable, "cell",
                 "this atlas cell's four-bar cannot be assembled at any crank angle"};
  const FourBarLengths& l = key.lengths;
  const FourBarLengths scaled{l.frame * crank, l.crank * crank, l.coupler * crank, l.rocker * crank};
  auto design = fourBarDesign(scaled, key.branch, lengthUnit,
                              CouplerPointSpec{key.point.along * scaled.coupler, key.point.across * scaled.coupler});
  if (!design) return design;
  design.value().omega = omega;
  if (range.fullRotation) return design;
  const AngleRange traced = tracedRange(range);
  design.value().fromDeg = radToDeg(traced.from);
  design.value().toDeg = radToDeg(traced.to);
  design.value().samples = samplesEveryHalfDegree(design.value().fromDeg, design.value().toDeg);
  return design;
}

}  // namespace linkwright::kinematics
