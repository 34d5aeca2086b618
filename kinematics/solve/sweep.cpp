#include "kinematics/solve/sweep.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/work_count.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/newton_group.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sample_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace linkwright::kinematics {
namespace {

// Branch refinement stops at steps of 1e-7 rad: near a toggle the two candidates are about
// (link length)·Δθ apart, and below this their separation drowns in the round-off of h²
// (≈ 1e-16·length², see rrr_dyad.h), so finer steps would only add noise. The depth cap
// (a full turn halved 40 times is 6e-12 rad) merely bounds the scratch space.
constexpr double kMinRefineStep = 1e-7;
constexpr int kMaxRefineDepth = 40;
// Refinement solves between two samples at most: a toggle needs a few dozen (one path down to
// kMinRefineStep), but a dyad held at its assembly limit by a rigid loop is ambiguous on every
// sub-step, and halving both halves to kMinRefineStep would take 2^17 solves a degree.
constexpr int kMaxRefineSolves = 256;
const SolveRequest kPositionsOnly{false, false, {}, {}, false};

// A dyad whose branch a sweep tracks, with what moves it: its parent points (`second` is
// absent for a slider, whose other parent is its guide), the link carrying its guide, and for
// an actuator the input, which is its length.
struct TrackedDyad {
  std::size_t point;
  std::size_t first;
  std::optional<std::size_t> second;
  std::optional<LinkId> guideLink;
  bool lengthIsInput = false;
};

// The dyads a scope solves, looked up once per sweep.
std::vector<TrackedDyad> dyadsIn(const Mechanism& m, const SolveScope& scope) {
  std::vector<TrackedDyad> out;
  for (const PointId p : scope.pointSteps) {
    const PointDefinition& def = m.points[p.index].definition;
    if (const auto* r = std::get_if<RrrPoint>(&def)) out.push_back({p.index, r->first.index, r->second.index, {}});
    if (const auto* s = std::get_if<RrpPoint>(&def)) out.push_back({p.index, s->first.index, {}, s->guide.link});
    if (const auto* a = std::get_if<ActuatorPoint>(&def))
      out.push_back({p.index, a->first.index, a->base.index, {}, true});
  }
  return out;
}

// An upper bound on |d| (at most √2 times it) without a square root: the branch test below
// only needs to overstate how far points moved, never understate it.
double displacementBound(const Eigen::Vector2d& d) { return std::abs(d.x()) + std::abs(d.y()); }

// How far a guide on link k can move the point of it nearest a slider between poses a and b:
// its ends' displacement, plus the rotation times the reach of the guide from the link.
double guideMotion(const Mechanism& m, LinkId k, const Pose& a, const Pose& b) {
  const Link& l = m.links[k.index];
  const double ends = std::max((b.position[l.first.index] - a.position[l.first.index]).norm(),
                               (b.position[l.second.index] - a.position[l.second.index]).norm());
  const double turn = std::abs(wrapAngle(b.linkAngle[k.index] - a.linkAngle[k.index]));
  double reach = 0.0;
  for (const Eigen::Vector2d& p : b.position) reach = std::max(reach, (p - b.position[l.first.index]).norm());
  return ends + turn * reach;
}

// True unless every dyad provably stays away from its toggle between poses a and b. The gap to
// an assembly limit (Pose::assemblyGap) changes no faster than the parents move, so it cannot
// close if the gaps at both ends exceed the parents' displacement (doubled, since a chord
// understates the path). Input steps over `maxStep` are always split: there a chord says too
// little about the path (inputStepLimit).
// `dyads`: the RRR, RRP and actuator points solved (dyadsIn).
bool branchAmbiguous(const Mechanism& m, std::span<const TrackedDyad> dyads, double maxStep, double aAngle,
                     const Pose& a, double bAngle, const Pose& b) {
  if (std::abs(bAngle - aAngle) > maxStep) return true;
  for (const TrackedDyad& d : dyads) {
    double motion = displacementBound(b.position[d.first] - a.position[d.first]);
    if (d.lengthIsInput) motion += std::abs(bAngle - aAngle);
    if (d.second) motion += displacementBound(b.position[*d.second] - a.position[*d.second]);
    if (d.guideLink) motion += guideMotion(m, *d.guideLink, a, b);
    if (a.assemblyGap[d.point] + b.assemblyGap[d.point] <= 2.0 * motion) return true;
  }
  return false;
}

// The largest input step whose chords the branch test trusts: half a radian of crank, half the
// radius of an arc path; a straight path or an actuator moves its point along the chord.
double inputStepLimit(const Mechanism& m) {
  const auto driver = driverPoint(m);
  if (!driver) return 0.5;
  const PointDefinition& def = m.points[driver->index].definition;
  if (const auto* d = std::get_if<PathPoint>(&def)) {
    if (const auto* arc = std::get_if<ArcPath>(&d->path)) return 0.5 * arc->radius;
    return std::numeric_limits<double>::infinity();
  }
  if (std::holds_alternative<ActuatorPoint>(def)) return std::numeric_limits<double>::infinity();
  return 0.5;
}

void allocate(const Mechanism& m, const SweepSpec& spec, std::size_t first, std::size_t n, const SolveRequest& request,
              const SolveScope& scope, SweepResult& out);
void summarize(const Mechanism& m, const SweepSpec& spec, std::size_t first, bool afterFailure, SweepResult& out,
               SweepSummary& summary);

// Solves one sweep: tracks branches from sample to sample and writes the columns, a window of
// them at a time (the whole sweep is one window unless sweepInWindows asks for smaller ones).
// `out` is allocated for the first window; each full window is finished, summarized and handed
// to the sink, and the same columns then hold the next.
class Tracker {
public:
  Tracker(const Mechanism& m, const SweepSpec& spec, const SolveRequest& request, const SolveScope& scope,
          SweepResult& out, std::size_t window, SweepSummary& summary)
      : m_mech(m), m_spec(spec), m_request(request), m_scope(scope), m_out(out), m_writer(m, out), m_window(window),
        m_summary(summary), m_dyads(dyadsIn(m, scope)), m_maxStep(inputStepLimit(m)), m_scratch(kMaxRefineDepth + 1) {
    for (Pose& p : m_poses) preparePose(m, p);
    m_predicted.assign(m.points.size(), Eigen::Vector2d::Zero());
    for (std::size_t i = 0; i < m.points.size(); ++i)
      if (std::holds_alternative<FreePoint>(m.points[i].definition)) m_freePoints.push_back(i);
  }

  // Samples run in blocks (solveBlock) while the branches are plainly continuous; the first
  // sample, any sample near a toggle or a gap, and linkages with free points (whose Newton
  // starts from the samples before) run one at a time. A block never crosses the end of a
  // window. The whole sweep in its windows; false at the first block or sample after `cancel`
  // became true (with the columns half written).
  bool run(const std::atomic<bool>* cancel) {
    while (nextWindow(cancel)) {
    }
    return !m_cancelled;
  }

  // Solves the next window into the columns and finishes it (ground pivots, summary): true
  // when it is there to read, from sample m_first; false when the sweep has no more samples,
  // or `cancel` became true (m_cancelled). The order of the solves is the same whatever the
  // windows: a block that ends a window is followed by one sample alone in the next.
  bool nextWindow(const std::atomic<bool>* cancel) {
    if (m_started) {
      if (m_next >= m_spec.samples) return false;
      m_first += m_out.size();
      allocate(m_mech, m_spec, m_first, std::min(m_window, m_spec.samples - m_first), m_out.request, m_scope, m_out);
    }
    m_started = true;
    if (m_oneFirst && m_next < windowEnd()) solveOne(m_next++);
    m_oneFirst = false;
    while (m_next < windowEnd()) {
      if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
        m_cancelled = true;
        return false;
      }
      if (m_haveLast && m_freePoints.empty()) m_next = solveBlock(m_next);
      if (m_next == windowEnd()) {
        m_oneFirst = m_next < m_spec.samples;
        break;
      }
      solveOne(m_next++);
    }
    m_writer.finish(m_mech, m_out);
    summarize(m_mech, m_spec, m_first, m_afterFailure, m_out, m_summary);
    m_afterFailure = m_out.size() > 0 && !m_out.assembled(m_out.size() - 1);
    return true;
  }

  std::size_t first() const { return m_first; }

private:
  std::size_t windowEnd() const { return m_first + m_out.size(); }

  void solveOne(std::size_t j) {
    const DriverState driver = sweepDriver(m_spec, j);
    const double angle = driver.position;
    const std::size_t at = j - m_first;
    m_out.inputAngle[at] = angle;
    m_continued = true;
    const PoseReport report = solveSample(driver);
    m_out.report[at] = report;
    if (report.status == PoseStatus::NotAssemblable) {
      m_writer.writeNothing(at);
      m_haveLast = m_haveBefore = false;
      m_run = 0;
      return;
    }
    if (report.status == PoseStatus::Singular) clearRates(*m_current);
    m_writer.write(at, *m_current);
    advance(angle);
  }

  // Solves up to kMaxBlock samples from j at once with the last sample's branches
  // (solveBlockInto: their chains of roots and divisions overlap in the processor), and keeps
  // them up to the first one that failed or whose branch continuity is not plain: that one,
  // whose index is returned, is then solved alone, with refinement. Same numbers as solveOne.
  std::size_t solveBlock(std::size_t j) {
    const std::size_t count = std::min(kMaxBlock, windowEnd() - j);
    if (m_block[0].position.size() != m_mech.points.size()) {
      for (std::size_t b = 0; b < kMaxBlock; ++b) {
        preparePose(m_mech, m_block[b]);
        m_blockPoses[b] = &m_block[b];
      }
    }
    std::array<DriverState, kMaxBlock>& drivers = m_blockDrivers;
    std::array<PoseReport, kMaxBlock>& reports = m_blockReports;
    for (std::size_t b = 0; b < count; ++b) drivers[b] = sweepDriver(m_spec, j + b);
    const BranchGuide keep{m_last->branchSign, {}};
    const std::size_t solved = solveBlockInto(m_mech, {drivers.data(), count}, m_request, {m_blockPoses.data(), count},
                                              keep, m_scope, {reports.data(), count});
    std::size_t kept = 0;
    for (; kept < solved; ++kept) {
      const double angle = drivers[kept].position;
      const double previousAngle = kept == 0 ? m_lastAngle : drivers[kept - 1].position;
      const Pose& previous = kept == 0 ? *m_last : m_block[kept - 1];
      if (reports[kept].status == PoseStatus::NotAssemblable ||
          branchAmbiguous(m_mech, m_dyads, m_maxStep, previousAngle, previous, angle, m_block[kept]))
        break;
    }
    const std::size_t at = j - m_first;
    for (std::size_t b = 0; b < kept; ++b) {
      m_out.inputAngle[at + b] = drivers[b].position;
      m_out.report[at + b] = reports[b];
      if (reports[b].status == PoseStatus::Singular) clearRates(m_block[b]);
    }
    m_writer.write(at, {m_block.data(), kept});
    if (kept > 0) keepBlockEnd(kept, drivers);
    return j + kept;
  }

  // The last kept block pose becomes the last sample, the one before it (or the old last) the
  // sample before: swaps, no copies.
  void keepBlockEnd(std::size_t kept, const std::array<DriverState, kMaxBlock>& drivers) {
    std::swap(*m_last, m_block[kept - 1]);
    std::swap(m_before->position, m_block[kept >= 2 ? kept - 2 : 0].position);
    m_beforeAngle = kept >= 2 ? drivers[kept - 2].position : m_lastAngle;
    m_lastAngle = drivers[kept - 1].position;
    m_haveBefore = true;
  }

  PoseReport solve(const DriverState& driver, const SolveRequest& request, Pose& pose,
                   const BranchGuide& guide = {}) const {
    return solvePoseInto(m_mech, driver, request, pose, guide, &m_scope);
  }

  // The current pose becomes the last, the last the one before it: the three poses rotate, no
  // copies. Free points then warm-start from their path extrapolated (predictFreePoints).
  void advance(double angle) {
    Pose* const oldest = m_before;
    m_before = m_last;
    m_last = m_current;
    m_current = oldest;
    m_run = m_continued ? std::min(m_run + 1, 3) : 1;
    if (!m_freePoints.empty()) predictFreePoints();
    m_beforeAngle = m_lastAngle;
    m_haveBefore = m_haveLast;
    m_lastAngle = angle;
    m_haveLast = true;
  }

  // Newton's start for the next sample, written into the current pose, which still holds the
  // sample three back. Samples are evenly spaced in the input (or in time on a time base), so
  // in units of one sample the parabola through a free point's last three positions gives
  // q(0) ≈ q(−1) + Δ1 + Δ2, with Δ1 = q(−1) − q(−2) and Δ2 = Δ1 − (q(−2) − q(−3)), off by
  // about q‴h³: Newton's first step then meets the tolerance (its error squares), where the
  // last sample's positions, off by q′h, took two. Only where the path is smooth at this
  // spacing, the largest |Δ2| at most half the largest |Δ1| (on a circle, steps up to 29°): on
  // a coarse grid the parabola can overshoot by more than a step, and the last sample's
  // positions are the safer start. The same after a gap or a lock (m_run < 3: the last samples
  // do not form one path). The other points keep the last sample's positions.
  void predictFreePoints() {
    std::vector<Eigen::Vector2d>& next = m_current->position;
    const std::vector<Eigen::Vector2d>& last = m_last->position;
    const std::vector<Eigen::Vector2d>& before = m_before->position;
    double step = 0.0;
    double bend = 0.0;
    for (const std::size_t i : m_freePoints) {
      const Eigen::Vector2d d1 = last[i] - before[i];
      m_predicted[i] = d1 - (before[i] - next[i]);  // Δ2, for now
      step = std::max(step, d1.squaredNorm());
      bend = std::max(bend, m_predicted[i].squaredNorm());
    }
    const bool smooth = m_run >= 3 && bend <= 0.25 * step;
    for (const std::size_t i : m_freePoints)
      m_predicted[i] = smooth ? Eigen::Vector2d(2.0 * last[i] - before[i] + m_predicted[i]) : last[i];
    std::copy(last.begin(), last.end(), next.begin());  // same sizes: no allocation
    for (const std::size_t i : m_freePoints) next[i] = m_predicted[i];
    m_current->assembled = true;  // a warm start (pose_solver.cpp's startFreeGroup)
  }

  PoseReport solveSample(const DriverState& driver) {
    const double angle = driver.position;
    if (!m_haveLast) return solve(driver, m_request, *m_current);
    m_refineSolves = 0;
    const BranchGuide keep{m_last->branchSign, {}};
    PoseReport report = solve(driver, m_request, *m_current, keep);
    if (report.status == PoseStatus::NotAssemblable ||
        !branchAmbiguous(m_mech, m_dyads, m_maxStep, m_lastAngle, *m_last, angle, *m_current))
      return report;
    const Eigen::Vector2d* before = m_haveBefore ? m_before->position.data() : nullptr;
    if (!refine(0, m_lastAngle, *m_last, m_beforeAngle, before, angle, scratch(0))) {
      // The path leaves the assemblable region between two samples: start afresh here.
      const PoseReport afresh = solve(driver, m_request, *m_current);
      if (afresh.status != PoseStatus::NotAssemblable) m_out.lockedBetween.push_back({m_lastAngle, angle});
      m_continued = false;  // a jump: the path before it says nothing about the path after
      return afresh;
    }
    const BranchGuide tracked{m_scratch[0].branchSign, {}};
    m_current->position = m_scratch[0].position;  // free points start from the tracked solution
    return solve(driver, m_request, *m_current, tracked);
  }

  // Positions at angle b continuing from pose `a` at angle aAngle; halves the step while a
  // branch switch cannot be ruled out. `before` (may be null) is the path before `a`.
  bool refine(int depth, double aAngle, const Pose& a, double beforeAngle, const Eigen::Vector2d* before, double b,
              Pose& out) {
    // Free points warm-start from the pose this step continues, not from stale scratch.
    out.position = a.position;
    out.assembled = true;
    const BranchGuide keep{a.branchSign, {}};
    if (solve({b, 0.0, 0.0}, kPositionsOnly, out, keep).status == PoseStatus::NotAssemblable) return false;
    if (!branchAmbiguous(m_mech, m_dyads, m_maxStep, aAngle, a, b, out)) return true;
    if (std::abs(b - aAngle) <= kMinRefineStep || depth == kMaxRefineDepth || ++m_refineSolves > kMaxRefineSolves) {
      if (before == nullptr) return true;
      // A driver at rest between samples (a dwell) gives no direction to extrapolate.
      const double ratio = aAngle != beforeAngle ? (b - aAngle) / (aAngle - beforeAngle) : 0.0;
      for (std::size_t i = 0; i < m_predicted.size(); ++i)
        m_predicted[i] = a.position[i] + ratio * (a.position[i] - before[i]);
      const BranchGuide nearest{{}, m_predicted};
      solve({b, 0.0, 0.0}, kPositionsOnly, out, nearest);
      return true;
    }
    const double mid = 0.5 * (aAngle + b);
    Pose& midPose = scratch(depth + 1);
    if (!refine(depth + 1, aAngle, a, beforeAngle, before, mid, midPose)) return false;
    return refine(depth + 1, mid, midPose, aAngle, a.position.data(), b, out);
  }

  // Refinement's poses, sized on first use: most sweeps never refine deeper than a few levels,
  // so the 41 levels' storage is not allocated up front.
  Pose& scratch(int depth) {
    Pose& p = m_scratch[static_cast<std::size_t>(depth)];
    if (p.position.size() != m_mech.points.size()) preparePose(m_mech, p);
    return p;
  }

  const Mechanism& m_mech;
  const SweepSpec& m_spec;
  const SolveRequest& m_request;
  const SolveScope& m_scope;
  SweepResult& m_out;
  SampleWriter m_writer;
  std::size_t m_window;  // samples per window (the whole sweep: one window, kept in m_out)
  SweepSummary& m_summary;
  std::size_t m_first = 0;  // the window's first sample in the sweep
  std::size_t m_next = 0;   // the next sample to solve
  bool m_started = false;   // the first window has been asked for
  bool m_oneFirst = false;  // a block ended the last window: the next starts with one sample alone
  bool m_cancelled = false;
  bool m_afterFailure = false;  // the sample before the window did not assemble
  std::vector<TrackedDyad> m_dyads;
  double m_maxStep;
  Pose m_poses[3];
  std::array<Pose, kMaxBlock> m_block;  // a block's poses, and their drivers and reports
  std::array<Pose*, kMaxBlock> m_blockPoses{};
  std::array<DriverState, kMaxBlock> m_blockDrivers{};
  std::array<PoseReport, kMaxBlock> m_blockReports{};
  int m_refineSolves = 0;  // refinement solves for the current sample, against kMaxRefineSolves
  Pose* m_current = &m_poses[0];
  Pose* m_last = &m_poses[1];
  Pose* m_before = &m_poses[2];
  std::vector<Pose> m_scratch;
  std::vector<Eigen::Vector2d> m_predicted;
  std::vector<std::size_t> m_freePoints;  // their indices; Newton warm-starts them from a prediction
  double m_lastAngle = 0.0, m_beforeAngle = 0.0;
  int m_run = 0;            // consecutive assembled samples ending at the last, no lock between (at most 3)
  bool m_continued = true;  // whether the sample being solved continues the last one's path
  bool m_haveLast = false, m_haveBefore = false;
};

// Sizes `columns` to one column of n samples per selected entry and an empty one for the
// others (no columns at all for a quantity not wanted), reusing the storage they already have:
// a sweep repeated into the same result (a drag, a benchmark) allocates nothing and touches no
// new pages. Values are written by the sweep.
template <typename T>
void sizeColumns(std::vector<std::vector<T>>& columns, const std::vector<unsigned char>& selected, bool wanted,
                 std::size_t n) {
  if (!wanted) {
    columns.clear();
    return;
  }
  columns.resize(selected.size());
  for (std::size_t i = 0; i < selected.size(); ++i) {
    if (selected[i] != 0) columns[i].resize(n);
    else columns[i].clear();
  }
}

// Sizes `out` for the window of `n` samples from `first`: its columns (a later window is never
// longer than the first, so its columns shrink in place and the writer's pointers stay valid),
// its instants on a time base, and no runs yet.
void allocate(const Mechanism& m, const SweepSpec& spec, std::size_t first, std::size_t n, const SolveRequest& request,
              const SolveScope& scope, SweepResult& out) {
  out.request = request;
  out.inputAngle.resize(n);
  out.report.resize(n);
  sizeColumns(out.position, scope.reportPoint, true, n);
  sizeColumns(out.velocity, scope.reportPoint, request.velocities, n);
  sizeColumns(out.acceleration, scope.reportPoint, request.accelerations, n);
  sizeColumns(out.linkAngle, scope.reportLink, true, n);
  sizeColumns(out.linkOmega, scope.reportLink, request.velocities, n);
  sizeColumns(out.linkAlpha, scope.reportLink, request.accelerations, n);
  std::vector<unsigned char> dyads = scope.reportPoint;
  for (std::size_t i = 0; i < dyads.size(); ++i)
    dyads[i] = dyads[i] != 0 && hasTransmissionAngle(m.points[i].definition) ? 1 : 0;
  if (!request.transmissionAngles) std::fill(dyads.begin(), dyads.end(), 0);
  sizeColumns(out.transmissionAngle, dyads, true, n);
  out.time.resize(spec.time ? n : 0);
  for (std::size_t j = 0; j < out.time.size(); ++j) out.time[j] = sweepTime(spec, first + j);
  out.notAssembled.clear();
  out.singularAngles.clear();
  out.lockedBetween.clear();
  out.firstFailure.reset();
}

// Collects the window's runs of failed samples and its singular samples once it is solved,
// into the window and the whole sweep's summary (`afterFailure`: the sample before the window
// failed, so a run there goes on).
void summarize(const Mechanism& m, const SweepSpec& spec, std::size_t first, bool afterFailure, SweepResult& out,
               SweepSummary& summary) {
  Pose scratch;
  summary.samples += out.size();
  summary.lockedBetween.insert(summary.lockedBetween.end(), out.lockedBetween.begin(), out.lockedBetween.end());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const PoseReport& r = out.report[j];
    if (r.status == PoseStatus::Singular) out.singularAngles.push_back(out.inputAngle[j]);
    if (r.status != PoseStatus::NotAssemblable) ++summary.assembledSamples;
    if (r.status == PoseStatus::Ok) continue;
    if (!summary.firstFailure && r.status == PoseStatus::NotAssemblable) {
      preparePose(m, scratch);
      solvePoseInto(m, sweepDriver(spec, first + j), kPositionsOnly, scratch);
      summary.firstFailure = describeFailure(m, r, scratch, out.inputAngle[j]);
      out.firstFailure = summary.firstFailure;
    }
    if (r.status != PoseStatus::NotAssemblable) continue;
    const bool continues = j > 0 && out.report[j - 1].status == PoseStatus::NotAssemblable;
    if (continues) out.notAssembled.back().to = out.inputAngle[j];
    else out.notAssembled.push_back({out.inputAngle[j], out.inputAngle[j]});
    if (continues || (j == 0 && afterFailure)) summary.notAssembled.back().to = out.inputAngle[j];
    else summary.notAssembled.push_back({out.inputAngle[j], out.inputAngle[j]});
  }
  summary.singularAngles.insert(summary.singularAngles.end(), out.singularAngles.begin(), out.singularAngles.end());
}

}  // namespace

bool SweepResult::lockedAfter(std::size_t sample) const {
  return sample + 1 < size() && std::any_of(lockedBetween.begin(), lockedBetween.end(), [&](const AngleRange& step) {
           return step.from == inputAngle[sample] && step.to == inputAngle[sample + 1];
         });
}

std::optional<Error> checkTimeBase(const TimeBase& time, InputKind kind) {
  if (auto e = checkMotionLaw(time.law, kind)) return e;
  if (auto e = checkMagnitude(time.fromTime, "from time", kMaxTime, "s")) return e;
  if (auto e = checkMagnitude(time.toTime, "to time", kMaxTime, "s")) return e;
  if (time.toTime < time.fromTime)
    return Error{ErrorCode::InvalidValue, "to time",
                 "to time must not be before from time (got " + formatNumber(time.fromTime) + " to " +
                     formatNumber(time.toTime) + " s)"};
  // The laws are monotonic between their ends (a table is bounded by its rows), so the
  // positions at the two ends bound every sample's: within the domain's.
  const InputDomain domain = inputDomain(kind);
  for (const double t : {time.fromTime, time.toTime})
    if (auto e =
            checkComputedMagnitude(motionAt(time.law, t).position,
                                   std::string(kind == InputKind::Angle ? "the law's angle" : "the law's position") +
                                       " at " + formatNumber(t) + " s",
                                   domain.position, domain.positionUnit))
      return e;
  if (const auto span = lawTimeSpan(time.law); span && (time.fromTime < span->first || time.toTime > span->second))
    return Error{ErrorCode::InvalidValue, "from time",
                 "the times " + formatNumber(time.fromTime) + " to " + formatNumber(time.toTime) +
                     " s leave the law's table, which runs from " + formatNumber(span->first) + " to " +
                     formatNumber(span->second) + " s"};
  return std::nullopt;
}

std::optional<Error> checkSweepSpec(const SweepSpec& spec, InputKind kind) {
  if (spec.time)
    if (auto e = checkTimeBase(*spec.time, kind)) return e;
  const InputDomain d = inputDomain(kind);
  const bool angle = kind == InputKind::Angle;
  if (auto e = checkMagnitude(spec.fromAngle, angle ? "from angle" : "from input", d.position, d.positionUnit))
    return e;
  if (auto e = checkMagnitude(spec.toAngle, angle ? "to angle" : "to input", d.position, d.positionUnit)) return e;
  if (auto e = checkMagnitude(spec.omega, d.rateName, d.rate, d.rateUnit)) return e;
  if (auto e = checkMagnitude(spec.alpha, d.accelerationName, d.acceleration, d.accelerationUnit)) return e;
  if (spec.samples == 0 || spec.samples > static_cast<std::size_t>(kMaxSamples))
    return Error{
        ErrorCode::InvalidValue, "samples",
        "samples must be between 1 and " + std::to_string(kMaxSamples) + " (got " + std::to_string(spec.samples) + ")"};
  return std::nullopt;
}

double sweepTime(const SweepSpec& spec, std::size_t index) {
  if (!spec.time) return 0.0;
  const TimeBase& t = *spec.time;
  if (spec.samples <= 1) return t.fromTime;
  const double u = static_cast<double>(index) / static_cast<double>(spec.samples - 1);
  return index + 1 == spec.samples ? t.toTime : t.fromTime + u * (t.toTime - t.fromTime);
}

double sweepParameter(const SweepSpec& spec, std::size_t index) {
  return spec.time ? sweepTime(spec, index) : sweepAngle(spec, index);
}

DriverState sweepDriverAt(const SweepSpec& spec, double parameter) {
  if (!spec.time) return {parameter, spec.omega, spec.alpha};
  const DriverState s = motionAt(spec.time->law, parameter);
  return {s.position, s.velocity, s.acceleration};
}

DriverState sweepDriver(const SweepSpec& spec, std::size_t index) {
  if (!spec.time) return {sweepAngle(spec, index), spec.omega, spec.alpha};
  const DriverState s = motionAt(spec.time->law, sweepTime(spec, index));
  return {s.position, s.velocity, s.acceleration};
}

double sweepAngle(const SweepSpec& spec, std::size_t index) {
  if (spec.time) return sweepDriver(spec, index).position;
  if (spec.samples <= 1) return spec.fromAngle;
  const double t = static_cast<double>(index) / static_cast<double>(spec.samples - 1);
  return index + 1 == spec.samples ? spec.toAngle : spec.fromAngle + t * (spec.toAngle - spec.fromAngle);
}

namespace {

// The checks every sweep makes before it solves anything, and its request as solved.
Result<SolveRequest> checkedRequest(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request) {
  if (auto e = checkMechanism(mechanism)) return *e;
  if (auto e = checkSweepSpec(spec, inputKind(mechanism))) return *e;
  if (auto e = checkNewtonSettings(request.newton)) return *e;
  if (auto e = checkSelection(mechanism, request.only)) return *e;
  SolveRequest normalized = request;
  normalized.velocities = request.velocities || request.accelerations;
  return normalized;
}

}  // namespace

std::optional<Error> sweepInto(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                               SweepResult& out, const std::atomic<bool>* cancel) {
  const auto normalized = checkedRequest(mechanism, spec, request);
  if (!normalized) return normalized.error();
  countSweep(spec.samples);
  const SolveScope scope = scopeOf(mechanism, normalized->only);
  allocate(mechanism, spec, 0, spec.samples, *normalized, scope, out);
  SweepSummary summary;
  if (!Tracker(mechanism, spec, out.request, scope, out, spec.samples, summary).run(cancel))
    return Error{ErrorCode::Cancelled, "sweep", "the sweep was cancelled"};
  return std::nullopt;
}

struct SweepWindows::State {
  State(const Mechanism& m, const SweepSpec& s, const SolveRequest& request, std::size_t window)
      : mechanism(m), spec(s), scope(scopeOf(mechanism, request.only)) {
    allocate(mechanism, spec, 0, std::min(window, spec.samples), request, scope, part);
    tracker.emplace(mechanism, spec, part.request, scope, part, window, summary);
  }
  Mechanism mechanism;
  SweepSpec spec;
  SolveScope scope;
  SweepResult part;
  SweepSummary summary;
  std::optional<Tracker> tracker;  // reads the members above, so it is made after them
};

Result<SweepWindows> SweepWindows::start(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                                         std::size_t window) {
  const auto normalized = checkedRequest(mechanism, spec, request);
  if (!normalized) return normalized.error();
  countSweep(spec.samples);
  SweepWindows out;
  out.m_state = std::make_unique<State>(mechanism, spec, *normalized, std::max<std::size_t>(window, 1));
  return out;
}

SweepWindows::SweepWindows() = default;
SweepWindows::SweepWindows(SweepWindows&&) noexcept = default;
SweepWindows& SweepWindows::operator=(SweepWindows&&) noexcept = default;
SweepWindows::~SweepWindows() = default;

const SweepResult* SweepWindows::next(const std::atomic<bool>* cancel) {
  return m_state->tracker->nextWindow(cancel) ? &m_state->part : nullptr;
}

std::size_t SweepWindows::first() const { return m_state->tracker->first(); }

const SweepSummary& SweepWindows::summary() const { return m_state->summary; }

Result<SweepSummary> sweepInWindows(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                                    std::size_t window, const SweepWindowSink& sink) {
  auto started = SweepWindows::start(mechanism, spec, request, window);
  if (!started) return started.error();
  SweepWindows windows = std::move(started).value();
  while (const SweepResult* part = windows.next())
    if (!sink(*part, windows.first()))
      return Error{ErrorCode::Cancelled, "sweep", "the sweep was stopped by its reader"};
  return windows.summary();
}

void copySampleToPose(const SweepResult& s, std::size_t j, Pose& pose) {
  for (std::size_t i = 0; i < pose.position.size(); ++i) {
    pose.position[i] = s.position[i][j];
    pose.velocity[i] = s.velocity[i][j];
    pose.acceleration[i] = s.acceleration[i][j];
  }
  for (std::size_t k = 0; k < pose.linkAngle.size(); ++k) {
    pose.linkAngle[k] = s.linkAngle[k][j];
    pose.linkOmega[k] = s.linkOmega[k][j];
    pose.linkAlpha[k] = s.linkAlpha[k][j];
  }
}

Result<SweepResult> sweep(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request) {
  SweepResult out;
  if (auto e = sweepInto(mechanism, spec, request, out)) return *e;
  return out;
}

}  // namespace linkwright::kinematics
