#include "kinematics/synthesis/path_generation.h"

#include "kinematics/model/number_text.h"
#include "kinematics/synthesis/placed_fourbar.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/synthesis/defects.h"
#include "kinematics/synthesis/path_model.h"

#include <Eigen/Geometry>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <tuple>

namespace linkwright::kinematics {
namespace {

using path_model::Linkage;
using path_model::Timing;

constexpr std::size_t kMinTargets = 4;
constexpr std::size_t kMaxTargets = 10;
// Two local minima are the same linkage when every pivot, length and offset agrees to this
// (normalised units): LM stops within ~1e-8 of a minimum, distinct minima differ by far more.
constexpr double kSameMinimum = 1e-4;
// A result assembles when every gap is below this (normalised): well inside the pose solver's
// slack, kAssemblyTolerance·(b + c) ≥ 2e-12, so the independent solve assembles it too.
constexpr double kAssembledGap = 1e-13;
// The residual norm (normalised) at which a fit is exact: a few hundred ulps of the scale.
constexpr double kExactFit = 1e-13;

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

// The bounding box's centre and diagonal.
std::pair<Eigen::Vector2d, double> boundingBox(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {0.5 * (lo + hi), (hi - lo).norm()};
}

std::optional<Error> checkTargets(const PathTarget& t) {
  const std::size_t n = t.points.size();
  if (n < kMinTargets || n > kMaxTargets)
    return invalid("points", "points must number between 4 and 10 (got " + std::to_string(n) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string field = "points[" + std::to_string(i) + "]";
    if (auto e = checkCoordinate(t.points[i].x(), field + ".x")) return e;
    if (auto e = checkCoordinate(t.points[i].y(), field + ".y")) return e;
  }
  const double scale = boundingBox(t.points).second;
  for (std::size_t j = 1; j < n; ++j)
    for (std::size_t i = 0; i < j; ++i)
      if ((t.points[j] - t.points[i]).norm() <= 1e-9 * scale)
        return invalid("points[" + std::to_string(j) + "]", "point " + std::to_string(j + 1) +
                                                                " coincides with point " + std::to_string(i + 1) +
                                                                ": targets must be distinct");
  if (t.timing.empty()) return std::nullopt;
  if (t.timing.size() != n)
    return invalid("timing", "timing must give one crank angle per point, " + std::to_string(n) + " (got " +
                                 std::to_string(t.timing.size()) + ")");
  for (std::size_t i = 0; i < n; ++i)
    if (auto e = checkCoordinate(t.timing[i], "timing[" + std::to_string(i) + "]")) return e;
  for (std::size_t j = 1; j < n; ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (std::abs(wrapAngle(t.timing[j] - t.timing[i])) <= 1e-9)
        return invalid("timing[" + std::to_string(j) + "]",
                       "timing[" + std::to_string(j) + "] is timing[" + std::to_string(i) + "] (" +
                           formatNumber(t.timing[j]) +
                           " rad, modulo a turn): one crank angle puts the coupler "
                           "point at one place, not at two targets");
  return std::nullopt;
}

std::optional<Error> checkOptions(const PathOptions& o) {
  if (o.starts < 1 || o.starts > 100000)
    return invalid("starts", "starts must be between 1 and 100000 (got " + std::to_string(o.starts) + ")");
  if (o.keep < 1 || o.keep > 1000)
    return invalid("keep", "keep must be between 1 and 1000 (got " + std::to_string(o.keep) + ")");
  if (o.maxEvaluations < 10 || o.maxEvaluations > 100000)
    return invalid("maxEvaluations",
                   "maxEvaluations must be between 10 and 100000 (got " + std::to_string(o.maxEvaluations) + ")");
  return std::nullopt;
}

Linkage linkageOf(const PathMinimum& m) {
  Linkage l;
  l.o2 = m.o2;
  l.beta = m.beta;
  l.frame = m.frame;
  l.crank = m.crank;
  l.coupler = m.coupler;
  l.rocker = m.rocker;
  l.along = m.along;
  l.across = m.across;
  return l;
}

bool sameMinimum(const PathMinimum& a, const PathMinimum& b) {
  const Linkage p = linkageOf(a), q = linkageOf(b);
  const double differ =
      std::max({(p.o2 - q.o2).cwiseAbs().maxCoeff(), (p.o4() - q.o4()).cwiseAbs().maxCoeff(),
                std::abs(p.crank - q.crank), std::abs(p.coupler - q.coupler), std::abs(p.rocker - q.rocker),
                std::abs(p.along - q.along), std::abs(p.across - q.across)});
  return a.branch == b.branch && differ < kSameMinimum;
}

// Keeps the best `keep` distinct minima, best first.
void offer(std::vector<PathMinimum>& kept, PathMinimum m, std::size_t keep) {
  for (PathMinimum& k : kept)
    if (sameMinimum(k, m)) {
      if (m.worst < k.worst) k = std::move(m);
      std::stable_sort(kept.begin(), kept.end(),
                       [](const PathMinimum& a, const PathMinimum& b) { return a.worst < b.worst; });
      return;
    }
  const auto at =
      std::upper_bound(kept.begin(), kept.end(), m.worst, [](double w, const PathMinimum& k) { return w < k.worst; });
  kept.insert(at, std::move(m));
  if (kept.size() > keep) kept.pop_back();
}

// A random linkage in its own frame (O2 at the origin, frame along +x), mostly Grashof cranks,
// which turn through any spread of angles, sometimes anything.
Linkage randomLinkage(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto logUniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
  Linkage l;
  const bool crank = unit(rng) < 0.75;
  for (int attempt = 0; attempt < 20; ++attempt) {
    l.crank = logUniform(0.1, 0.6);
    l.frame = logUniform(0.2, 1.5);
    l.coupler = logUniform(0.2, 1.5);
    l.rocker = logUniform(0.2, 1.5);
    const double longest = std::max({l.frame, l.coupler, l.rocker});
    const double others = l.frame + l.coupler + l.rocker - longest;
    if (!crank || (l.crank < std::min({l.frame, l.coupler, l.rocker}) && l.crank + longest < others)) break;
  }
  l.along = l.coupler * (unit(rng) * 3.0 - 1.0);
  l.across = l.coupler * (unit(rng) * 3.0 - 1.5);
  return l;
}

// Places the local linkage by the similarity (and, if allowed, reflection) that best maps its
// coupler points to the targets (Procrustes). Angles are the crank's, local then absolute.
void placeBySimilarity(Linkage& l, Branch& branch, std::vector<double>& angles,
                       const std::vector<Eigen::Vector2d>& targets, bool mayReflect) {
  const std::size_t n = targets.size();
  struct Fit {
    double angle = 0.0, scale = 1.0, misfit = 0.0;
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  };
  const auto fit = [&](const std::vector<Eigen::Vector2d>& q) {
    Eigen::Vector2d qMean = Eigen::Vector2d::Zero(), tMean = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      qMean += q[i] / static_cast<double>(n);
      tMean += targets[i] / static_cast<double>(n);
    }
    double dot = 0.0, crossSum = 0.0, qq = 0.0, tt = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d a = q[i] - qMean, b = targets[i] - tMean;
      dot += a.dot(b);
      crossSum += cross(a, b);
      qq += a.squaredNorm();
      tt += b.squaredNorm();
    }
    Fit f;
    f.angle = std::atan2(crossSum, dot);
    const double along = std::hypot(dot, crossSum);
    f.scale = qq > 1e-12 ? along / qq : 1.0;
    f.misfit = tt - (qq > 1e-12 ? along * along / qq : 0.0);
    const Eigen::Rotation2Dd r(f.angle);
    f.shift = tMean - f.scale * (r * qMean);
    return f;
  };
  const auto points = [&](Branch b, double sign) {
    std::vector<Eigen::Vector2d> q(n);
    Linkage m = l;
    m.across *= sign;
    for (std::size_t i = 0; i < n; ++i) q[i] = path_model::couplerPosition(m, m.o4(), sign * angles[i], b).point;
    return q;
  };
  const Branch mirrored = branch == Branch::Open ? Branch::Crossed : Branch::Open;
  Fit best = fit(points(branch, 1.0));
  if (mayReflect) {
    // The mirror image about the frame line: the other branch, angles and P's offset negated.
    const Fit other = fit(points(mirrored, -1.0));
    if (other.misfit < best.misfit) {
      best = other;
      branch = mirrored;
      l.across = -l.across;
      for (double& a : angles) a = -a;
    }
  }
  const double s = std::clamp(best.scale, 0.05, 20.0);
  l.frame *= s;
  l.crank *= s;
  l.coupler *= s;
  l.rocker *= s;
  l.along *= s;
  l.across *= s;
  l.o2 = best.shift;
  l.beta = best.angle;
  for (double& a : angles) a += best.angle;
}

// A start: a random linkage and crank angles, placed on the targets.
Eigen::VectorXd drawStart(std::mt19937& rng, const std::vector<Eigen::Vector2d>& targets, const Timing& timing,
                          Branch& branch) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = targets.size();
  Linkage l = randomLinkage(rng);
  branch = unit(rng) < 0.5 ? Branch::Open : Branch::Crossed;
  const double first = (2.0 * unit(rng) - 1.0) * kPi;
  std::vector<double> angles(n);
  if (!timing.reference) {
    const double span = (kPi / 3.0 + unit(rng) * (2.0 * kPi * (1.0 - 1.0 / static_cast<double>(n)) - kPi / 3.0)) *
                        (unit(rng) < 0.5 ? 1.0 : -1.0);
    for (std::size_t i = 0; i < n; ++i) angles[i] = first + span * static_cast<double>(i) / static_cast<double>(n - 1);
  } else {
    const double start = *timing.reference == TimingReference::Start ? first : 0.0;
    for (std::size_t i = 0; i < n; ++i) angles[i] = start + timing.tau[i];
  }
  placeBySimilarity(l, branch, angles, targets, !timing.reference);
  Eigen::VectorXd x(path_model::parameterCount(timing, static_cast<int>(n)));
  path_model::encode(l, x);
  if (!timing.reference)
    for (std::size_t i = 0; i < n; ++i) x[path_model::kAngles + static_cast<Eigen::Index>(i)] = angles[i];
  else if (*timing.reference == TimingReference::Start) x[path_model::kAngles] = angles[0] - timing.tau[0];
  return x;
}

// Runs LM from x; the minimum, or nullopt if it does not assemble at every target.
std::optional<PathMinimum> refine(Eigen::VectorXd x, Branch branch, const std::vector<Eigen::Vector2d>& targets,
                                  const Timing& timing, int maxEvaluations) {
  path_model::Residual residual{&targets, &timing, branch};
  Eigen::LevenbergMarquardt<path_model::Residual> lm(residual);
  lm.setMaxfev(maxEvaluations);
  lm.setXtol(1e-12);
  lm.setFtol(1e-14);
  // minimize()'s loop, stopped also once the residual is at round-off: at an exact fit
  // MINPACK's relative tests see only noise and would spend the rest of the budget there.
  auto status = lm.minimizeInit(x);
  if (status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters) do
      status = lm.minimizeOneStep(x);
    while (status == Eigen::LevenbergMarquardtSpace::Running && lm.fnorm() > kExactFit);
  const Linkage l = path_model::decode(x);
  PathMinimum m;
  m.o2 = l.o2;
  m.beta = l.beta;
  m.frame = l.frame;
  m.crank = l.crank;
  m.coupler = l.coupler;
  m.rocker = l.rocker;
  m.along = l.along;
  m.across = l.across;
  m.branch = branch;
  const Eigen::Vector2d o4 = l.o4();
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const double angle = path_model::crankAngle(x, timing, i);
    const auto p = path_model::couplerPosition(l, o4, angle, branch);
    if (!(p.gap <= kAssembledGap) || !p.point.allFinite()) return std::nullopt;
    m.crankAngles.push_back(wrapAngle(angle));
    m.worst = std::max(m.worst, (p.point - targets[i]).norm());
  }
  return m;
}

// The minimum in the user's units, measured with the pose solver and checked for defects;
// nullopt if the solver cannot assemble it at some target (it then reaches no target there).
std::optional<PathCandidate> candidateFrom(const PathMinimum& m, const PathTarget& t, const Eigen::Vector2d& centre,
                                           double scale, const DefectBounds& bounds) {
  PathCandidate c;
  const Linkage l = linkageOf(m);
  c.o2 = centre + scale * l.o2;
  c.o4 = centre + scale * l.o4();
  // The frame as the mechanism has it (its pivots' distance), not as scaled: they differ in ulps.
  c.lengths = {(c.o4 - c.o2).norm(), scale * l.crank, scale * l.coupler, scale * l.rocker};
  c.couplerPoint = {scale * l.along, scale * l.across};
  c.branch = m.branch;
  c.crankAngles = m.crankAngles;
  c.start = m.start;
  c.secondsToFind = m.seconds;
  Design d;
  d.kind = "four-bar";
  d.mechanism = placedFourBar(c.o2, c.o4, c.lengths, c.branch, c.couplerPoint, t.lengthUnit);
  SolveRequest request{false, false};
  request.transmissionAngles = false;
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    const auto pose = solvePose(d.mechanism, {c.crankAngles[i], 0.0, 0.0}, request);
    if (!pose) return std::nullopt;
    c.distances.push_back((pose->position[fourbar::kCouplerPoint.index] - t.points[i]).norm());
    c.worstDistance = std::max(c.worstDistance, c.distances.back());
  }
  const double beta = std::atan2(c.o4.y() - c.o2.y(), c.o4.x() - c.o2.x());
  const CrankSpan span = crankSpanThrough(c.crankAngles);
  FourBarTask task{c.lengths,
                   {},
                   std::vector<Branch>(c.crankAngles.size(), c.branch),
                   t.needsFullRotation,
                   CrankSpan{span.from - beta, span.to - beta}};
  for (const double angle : c.crankAngles) task.crankAngles.push_back(angle - beta);
  FourBarCheck check = checkFourBar(task, bounds);
  if (check.grashof.inputFullyRotates) {
    d.fromDeg = radToDeg(c.crankAngles.front());
    d.toDeg = d.fromDeg + 360.0;
  } else {
    d.fromDeg = radToDeg(std::min(span.from, span.to));
    d.toDeg = radToDeg(std::max(span.from, span.to));
  }
  d.samples = std::max<std::size_t>(2, samplesEveryHalfDegree(d.fromDeg, d.toDeg));
  // Only targets near the ±1e9 edge of the input domain can give a design it refuses.
  if (checkDesign(d)) return std::nullopt;
  c.candidate = {std::move(d), c.worstDistance, check.grashof, check.minTransmission, std::move(check.defects)};
  return c;
}

// The targets in the search's normalised frame.
struct Normalised {
  Eigen::Vector2d centre;
  double scale = 0.0;
  std::vector<Eigen::Vector2d> targets;
  Timing timing;
  std::uint64_t fingerprint = 0;  // the search's (pathSearchFingerprint)
};

Normalised normalised(const PathTarget& target, const PathOptions& options) {
  Normalised n;
  n.fingerprint = pathSearchFingerprint(target, options);
  std::tie(n.centre, n.scale) = boundingBox(target.points);
  for (const Eigen::Vector2d& p : target.points) n.targets.push_back((p - n.centre) / n.scale);
  if (!target.timing.empty()) {
    n.timing.reference = target.timingReference;
    n.timing.tau = target.timing;
  }
  return n;
}

// Start s's own generator: a pure function of the seed and s.
std::mt19937 startGenerator(std::uint32_t seed, int start) {
  std::seed_seq seeds{seed, static_cast<std::uint32_t>(start)};
  return std::mt19937(seeds);
}

PathStartBlock runBlock(const Normalised& n, const PathOptions& options, int block, const std::atomic<bool>* cancel,
                        const PathProgress& progress) {
  using Clock = std::chrono::steady_clock;
  const auto began = Clock::now();
  PathStartBlock out;
  out.block = block;
  out.search = n.fingerprint;
  const int first = block * kPathStartsPerBlock;
  const int count = std::min(kPathStartsPerBlock, options.starts - first);
  for (int s = first; s < first + count; ++s) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
      out.cancelled = true;
      break;
    }
    std::mt19937 rng = startGenerator(options.seed, s);
    Branch branch = Branch::Open;
    const Eigen::VectorXd x = drawStart(rng, n.targets, n.timing, branch);
    if (auto m = refine(x, branch, n.targets, n.timing, options.maxEvaluations)) {
      m->start = s;
      m->seconds = std::chrono::duration<double>(Clock::now() - began).count();
      offer(out.kept, std::move(*m), options.keep);
    } else {
      ++out.startsNotAssembled;
    }
    ++out.startsRun;
    if (progress) progress(out.startsRun, count);
  }
  return out;
}

PathSynthesis merged(const PathTarget& target, const Normalised& n, const PathOptions& options,
                     const DefectBounds& bounds, std::vector<PathStartBlock> blocks) {
  std::sort(blocks.begin(), blocks.end(),
            [](const PathStartBlock& a, const PathStartBlock& b) { return a.block < b.block; });
  PathSynthesis out;
  out.scale = n.scale;
  out.cancelled = static_cast<int>(blocks.size()) < pathStartBlockCount(options);
  std::vector<PathMinimum> kept;
  for (PathStartBlock& b : blocks) {
    out.startsRun += b.startsRun;
    out.startsNotAssembled += b.startsNotAssembled;
    out.cancelled = out.cancelled || b.cancelled;
    for (PathMinimum& m : b.kept) offer(kept, std::move(m), options.keep);
  }
  for (const PathMinimum& m : kept) {
    if (auto c = candidateFrom(m, target, n.centre, n.scale, bounds)) out.candidates.push_back(std::move(*c));
    else ++out.startsNotAssembled;
  }
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const PathCandidate& a, const PathCandidate& b) { return a.worstDistance < b.worstDistance; });
  return out;
}

}  // namespace

int pathStartBlockCount(const PathOptions& options) {
  return (std::max(options.starts, 0) + kPathStartsPerBlock - 1) / kPathStartsPerBlock;
}

Result<PathStartBlock> runPathStartBlock(const PathTarget& target, const PathOptions& options, int block,
                                         const std::atomic<bool>* cancel, const PathProgress& progress) {
  if (auto e = checkTargets(target)) return *e;
  if (auto e = checkOptions(options)) return *e;
  const int blocks = pathStartBlockCount(options);
  if (block < 0 || block >= blocks)
    return invalid(
        "block", "block must be between 0 and " + std::to_string(blocks - 1) + " (got " + std::to_string(block) + ")");
  return runBlock(normalised(target, options), options, block, cancel, progress);
}

Result<PathSynthesis> pathSynthesisFromBlocks(const PathTarget& target, const PathOptions& options,
                                              const DefectBounds& bounds, std::vector<PathStartBlock> blocks) {
  if (auto e = checkTargets(target)) return *e;
  if (auto e = checkOptions(options)) return *e;
  if (auto e = checkPathStartBlocks(target, options, blocks)) return *e;
  return merged(target, normalised(target, options), options, bounds, std::move(blocks));
}

Result<PathSynthesis> synthesisePath(const PathTarget& target, const PathOptions& options, const DefectBounds& bounds,
                                     const std::atomic<bool>* cancel, const PathProgress& progress) {
  using Clock = std::chrono::steady_clock;
  const auto began = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - began).count(); };
  if (auto e = checkTargets(target)) return *e;
  if (auto e = checkOptions(options)) return *e;

  const Normalised n = normalised(target, options);
  std::vector<PathStartBlock> blocks;
  int done = 0;
  for (int b = 0; b < pathStartBlockCount(options); ++b) {
    const double blockBegan = elapsed();
    const int before = done;
    blocks.push_back(runBlock(n, options, b, cancel, [&](int inBlock, int) {
      done = before + inBlock;
      if (progress) progress(done, options.starts);
    }));
    for (PathMinimum& m : blocks.back().kept) m.seconds += blockBegan;  // from the search's start
    if (blocks.back().cancelled) break;
  }
  PathSynthesis out = merged(target, n, options, bounds, std::move(blocks));
  out.seconds = elapsed();
  return out;
}

}  // namespace linkwright::kinematics
