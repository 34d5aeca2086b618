#include "kinematics/solve/sweep.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/newton_group.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

// Branch refinement stops at steps of 1e-7 rad: near a toggle the two candidates are about
// (link length)·Δθ apart, and below this their separation drowns in the round-off of h²
// (≈ 1e-16·length², see rrr_dyad.h), so finer steps would only add noise. The depth cap
// (a full turn halved 40 times is 6e-12 rad) merely bounds the scratch space.
constexpr double kMinRefineStep = 1e-7;
constexpr int kMaxRefineDepth = 40;
constexpr SolveRequest kPositionsOnly{false, false};

double wrapToPi(double angle) { return std::remainder(angle, 2.0 * kPi); }

bool isDyad(const Mechanism& m, std::size_t i) {
  const PointDefinition& def = m.points[i].definition;
  return std::holds_alternative<RrrPoint>(def) || std::holds_alternative<RrpPoint>(def);
}

// How far the distance between a dyad's parents is from an assembly limit (l1 + l2 or
// |l1 − l2|): the dyad toggles, and its branch may switch, only where this reaches zero.
double limitGap(const RrrPoint& r, const Pose& pose) {
  const double L = (pose.position[r.second.index] - pose.position[r.first.index]).norm();
  return std::min(r.firstLength + r.secondLength - L, L - std::abs(r.firstLength - r.secondLength));
}

// For a slider: the rod length less the pin's distance from the guide. A moving guide adds its
// own motion, so its link's ends count toward the displacement below.
double limitGap(const Mechanism& m, const RrpPoint& p, const Pose& pose) {
  const GuideLine line = guideLineAt(m, p.guide, pose);
  const Eigen::Vector2d d = line.point - pose.position[p.first.index];
  return p.length - std::abs(line.direction.x() * d.y() - line.direction.y() * d.x());
}

// How far a guide on link k can move the point of it nearest a slider between poses a and b:
// its ends' displacement, plus the rotation times the reach of the guide from the link.
double guideMotion(const Mechanism& m, LinkId k, const Pose& a, const Pose& b) {
  const Link& l = m.links[k.index];
  const double ends = std::max((b.position[l.first.index] - a.position[l.first.index]).norm(),
                               (b.position[l.second.index] - a.position[l.second.index]).norm());
  const double turn = std::abs(wrapToPi(b.linkAngle[k.index] - a.linkAngle[k.index]));
  double reach = 0.0;
  for (const Eigen::Vector2d& p : b.position) reach = std::max(reach, (p - b.position[l.first.index]).norm());
  return ends + turn * reach;
}

// True unless every dyad provably stays away from its toggle between poses a and b. The gap
// changes no faster than the parents move, so it cannot close if the gaps at both ends exceed
// the parents' displacement (doubled, since a chord understates the path). Steps over half a
// radian are always split: there a chord says too little about the path.
bool branchAmbiguous(const Mechanism& m, double aAngle, const Pose& a, double bAngle, const Pose& b) {
  if (std::abs(bAngle - aAngle) > 0.5) return true;
  for (const Point& p : m.points) {
    if (const auto* r = std::get_if<RrrPoint>(&p.definition)) {
      const double motion = (b.position[r->first.index] - a.position[r->first.index]).norm() +
                            (b.position[r->second.index] - a.position[r->second.index]).norm();
      if (limitGap(*r, a) + limitGap(*r, b) <= 2.0 * motion) return true;
    } else if (const auto* s = std::get_if<RrpPoint>(&p.definition)) {
      double motion = (b.position[s->first.index] - a.position[s->first.index]).norm();
      if (s->guide.link) motion += guideMotion(m, *s->guide.link, a, b);
      if (limitGap(m, *s, a) + limitGap(m, *s, b) <= 2.0 * motion) return true;
    }
  }
  return false;
}

// Solves one sweep: tracks branches from sample to sample and writes the columns.
class Tracker {
public:
  Tracker(const Mechanism& m, const SweepSpec& spec, const SolveRequest& request, SweepResult& out)
      : m_mech(m), m_spec(spec), m_request(request), m_out(out), m_scratch(kMaxRefineDepth + 1) {
    preparePose(m, m_last);
    preparePose(m, m_current);
    preparePose(m, m_before);
    for (Pose& p : m_scratch) preparePose(m, p);
    m_predicted.assign(m.points.size(), Eigen::Vector2d::Zero());
  }

  void run() {
    for (std::size_t j = 0; j < m_spec.samples; ++j) {
      const double angle = sweepAngle(m_spec, j);
      m_out.inputAngle[j] = angle;
      const PoseReport report = solveSample(angle);
      m_out.report[j] = report;
      if (report.status == PoseStatus::NotAssemblable) {
        m_haveLast = m_haveBefore = false;
        continue;
      }
      store(j);
      m_before.position = m_last.position;  // same sizes: copies, no allocation
      m_beforeAngle = m_lastAngle;
      m_haveBefore = m_haveLast;
      m_last = m_current;
      m_lastAngle = angle;
      m_haveLast = true;
    }
  }

private:
  DriverState driver(double angle) const { return {angle, m_spec.omega, m_spec.alpha}; }

  PoseReport solveSample(double angle) {
    if (!m_haveLast) return solvePoseInto(m_mech, driver(angle), m_request, m_current);
    const BranchGuide keep{m_last.branchSign, {}};
    PoseReport report = solvePoseInto(m_mech, driver(angle), m_request, m_current, keep);
    if (report.status == PoseStatus::NotAssemblable || !branchAmbiguous(m_mech, m_lastAngle, m_last, angle, m_current))
      return report;
    const Eigen::Vector2d* before = m_haveBefore ? m_before.position.data() : nullptr;
    if (!refine(0, m_lastAngle, m_last, m_beforeAngle, before, angle, m_scratch[0])) {
      // The path leaves the assemblable region between two samples: start afresh here.
      return solvePoseInto(m_mech, driver(angle), m_request, m_current);
    }
    const BranchGuide tracked{m_scratch[0].branchSign, {}};
    m_current.position = m_scratch[0].position;  // free points start from the tracked solution
    return solvePoseInto(m_mech, driver(angle), m_request, m_current, tracked);
  }

  // Positions at angle b continuing from pose `a` at angle aAngle; halves the step while a
  // branch switch cannot be ruled out. `before` (may be null) is the path before `a`.
  bool refine(int depth, double aAngle, const Pose& a, double beforeAngle,
              const Eigen::Vector2d* before, double b, Pose& out) {
    // Free points warm-start from the pose this step continues, not from stale scratch.
    out.position = a.position;
    out.assembled = true;
    const BranchGuide keep{a.branchSign, {}};
    if (solvePoseInto(m_mech, driver(b), kPositionsOnly, out, keep).status == PoseStatus::NotAssemblable)
      return false;
    if (!branchAmbiguous(m_mech, aAngle, a, b, out)) return true;
    if (std::abs(b - aAngle) <= kMinRefineStep || depth == kMaxRefineDepth) {
      if (before == nullptr) return true;
      const double ratio = (b - aAngle) / (aAngle - beforeAngle);
      for (std::size_t i = 0; i < m_predicted.size(); ++i)
        m_predicted[i] = a.position[i] + ratio * (a.position[i] - before[i]);
      const BranchGuide nearest{{}, m_predicted};
      solvePoseInto(m_mech, driver(b), kPositionsOnly, out, nearest);
      return true;
    }
    const double mid = 0.5 * (aAngle + b);
    Pose& midPose = m_scratch[depth + 1];
    if (!refine(depth + 1, aAngle, a, beforeAngle, before, mid, midPose)) return false;
    return refine(depth + 1, mid, midPose, aAngle, a.position.data(), b, out);
  }

  void store(std::size_t j) {
    const bool rates = m_out.report[j].status == PoseStatus::Ok;
    for (std::size_t i = 0; i < m_mech.points.size(); ++i) {
      m_out.position[i][j] = m_current.position[i];
      if (rates && m_request.velocities) m_out.velocity[i][j] = m_current.velocity[i];
      if (rates && m_request.accelerations) m_out.acceleration[i][j] = m_current.acceleration[i];
      if (isDyad(m_mech, i)) m_out.transmissionAngle[i][j] = m_current.transmissionAngle[i];
    }
    for (std::size_t k = 0; k < m_mech.links.size(); ++k) {
      const double raw = m_current.linkAngle[k];
      m_out.linkAngle[k][j] = m_haveAnyAngle ? m_lastLinkAngle(k) + wrapToPi(raw - m_lastLinkAngle(k)) : raw;
      if (rates && m_request.velocities) m_out.linkOmega[k][j] = m_current.linkOmega[k];
      if (rates && m_request.accelerations) m_out.linkAlpha[k][j] = m_current.linkAlpha[k];
    }
    m_lastStored = j;
    m_haveAnyAngle = true;
  }

  double m_lastLinkAngle(std::size_t k) const { return m_out.linkAngle[k][m_lastStored]; }

  const Mechanism& m_mech;
  const SweepSpec& m_spec;
  const SolveRequest& m_request;
  SweepResult& m_out;
  Pose m_current, m_last, m_before;
  std::vector<Pose> m_scratch;
  std::vector<Eigen::Vector2d> m_predicted;
  double m_lastAngle = 0.0, m_beforeAngle = 0.0;
  bool m_haveLast = false, m_haveBefore = false, m_haveAnyAngle = false;
  std::size_t m_lastStored = 0;
};

void allocate(const Mechanism& m, std::size_t n, const SolveRequest& request, SweepResult& out) {
  const std::size_t points = m.points.size();
  const std::size_t links = m.links.size();
  const bool velocities = request.velocities || request.accelerations;
  out.request = {velocities, request.accelerations, request.newton};
  out.inputAngle.assign(n, 0.0);
  out.report.assign(n, PoseReport{});
  out.position.assign(points, std::vector<Eigen::Vector2d>(n, Eigen::Vector2d::Zero()));
  out.velocity.assign(velocities ? points : 0, std::vector<Eigen::Vector2d>(n, Eigen::Vector2d::Zero()));
  out.acceleration.assign(request.accelerations ? points : 0,
                          std::vector<Eigen::Vector2d>(n, Eigen::Vector2d::Zero()));
  out.linkAngle.assign(links, std::vector<double>(n, 0.0));
  out.linkOmega.assign(velocities ? links : 0, std::vector<double>(n, 0.0));
  out.linkAlpha.assign(request.accelerations ? links : 0, std::vector<double>(n, 0.0));
  out.transmissionAngle.assign(points, {});
  for (std::size_t i = 0; i < points; ++i)
    if (isDyad(m, i)) out.transmissionAngle[i].assign(n, 0.0);
}

// Collects the runs of failed samples and the singular samples after the loop.
void summarize(const Mechanism& m, const SweepSpec& spec, SweepResult& out) {
  Pose scratch;
  for (std::size_t j = 0; j < out.size(); ++j) {
    const PoseReport& r = out.report[j];
    if (r.status == PoseStatus::Singular) out.singularAngles.push_back(out.inputAngle[j]);
    if (r.status == PoseStatus::Ok) continue;
    if (!out.firstFailure && r.status == PoseStatus::NotAssemblable) {
      preparePose(m, scratch);
      solvePoseInto(m, {out.inputAngle[j], spec.omega, spec.alpha}, kPositionsOnly, scratch);
      out.firstFailure = describeFailure(m, r, scratch, out.inputAngle[j]);
    }
    if (r.status != PoseStatus::NotAssemblable) continue;
    const bool continues = j > 0 && out.report[j - 1].status == PoseStatus::NotAssemblable;
    if (continues) out.notAssembled.back().to = out.inputAngle[j];
    else out.notAssembled.push_back({out.inputAngle[j], out.inputAngle[j]});
  }
}

} // namespace

std::optional<Error> checkSweepSpec(const SweepSpec& spec) {
  if (auto e = checkFinite(spec.fromAngle, "from angle")) return e;
  if (auto e = checkFinite(spec.toAngle, "to angle")) return e;
  if (auto e = checkFinite(spec.omega, "omega")) return e;
  if (auto e = checkFinite(spec.alpha, "alpha")) return e;
  if (spec.samples == 0)
    return Error{ErrorCode::InvalidValue, "samples", "samples must be at least 1 (got 0)"};
  return std::nullopt;
}

double sweepAngle(const SweepSpec& spec, std::size_t index) {
  if (spec.samples <= 1) return spec.fromAngle;
  const double t = static_cast<double>(index) / static_cast<double>(spec.samples - 1);
  return index + 1 == spec.samples ? spec.toAngle : spec.fromAngle + t * (spec.toAngle - spec.fromAngle);
}

Result<SweepResult> sweep(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request) {
  if (auto e = checkMechanism(mechanism)) return *e;
  if (auto e = checkSweepSpec(spec)) return *e;
  if (auto e = checkNewtonSettings(request.newton)) return *e;
  SweepResult out;
  allocate(mechanism, spec.samples, request, out);
  Tracker(mechanism, spec, out.request, out).run();
  summarize(mechanism, spec, out);
  return out;
}

} // namespace linkwright::kinematics
