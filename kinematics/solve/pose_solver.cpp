#include "kinematics/solve/pose_solver.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/newton_group.h"
#include "kinematics/solve/rrp_dyad.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace linkwright::kinematics {
namespace {

// One pose being solved: its driver state, where it goes, and how its solve went.
struct Lane {
  const DriverState* driver = nullptr;
  Pose* pose = nullptr;
  PoseReport report{};
  bool ratesValid = true;  // false once a dyad was singular: later rates cannot be computed
  int newtonIterations = 0;
  double newtonResidual = 0.0;
};

// Solves a block of poses (lanes) step by step: each point, then each link, for every lane
// before the next. The loop over the lanes sits inside each step, so a step is dispatched once
// per block and its lanes run back to back: their chains of roots, divisions and library calls
// overlap in the processor. One pose is a block of one lane.
struct Solver {
  const Mechanism& m;
  bool wantVelocity;
  bool wantAcceleration;
  bool wantTransmission;
  const NewtonSettings& newton;
  const BranchGuide& guide;
  std::span<Lane> lanes;
  std::size_t live = lanes.size();  // lanes[live..] are not solved further: one before them failed

  static void markSingular(Lane& lane, std::size_t i) {
    if (lane.report.status == PoseStatus::Ok) lane.report = {PoseStatus::Singular, PointId{i}, AssemblyFailure::None};
    lane.ratesValid = false;
  }

  // Where Newton starts: the guide's prediction if given (a sweep's refinement at a toggle);
  // else this pose's own positions if they hold an assembly (the previous frame of a drag; in a
  // sweep, the free points' path extrapolated from the samples before: positions only move a
  // little between them); else the user's guesses. True unless it is the guesses.
  bool startFreeGroup(Pose& pose, std::size_t first, std::size_t last) const {
    if (!guide.predicted.empty()) {
      for (std::size_t i = first; i < last; ++i) pose.position[i] = guide.predicted[i];
      return true;
    }
    if (pose.assembled) return true;
    startFromGuesses(pose, first, last);
    return false;
  }

  void startFromGuesses(Pose& pose, std::size_t first, std::size_t last) const {
    for (std::size_t i = first; i < last; ++i) pose.position[i] = std::get<FreePoint>(m.points[i].definition).guess;
  }

  // A group of free points, by Newton. A warm start that fails to converge (a jump too far
  // from the last pose) is retried once from the guesses, the assembly the user means; if
  // that fails too, the linkage most likely cannot close here.
  bool freeGroup(Lane& lane, std::size_t first, std::size_t last) const {
    Pose& pose = *lane.pose;
    const bool rates = wantVelocity && lane.ratesValid;
    const bool warm = startFreeGroup(pose, first, last);
    NewtonOutcome out = solveFreeGroup(m, first, last, newton, rates, rates && wantAcceleration, pose);
    if (out.status == NewtonStatus::NoConvergence && warm) {
      lane.newtonIterations += out.iterations;
      startFromGuesses(pose, first, last);
      out = solveFreeGroup(m, first, last, newton, rates, rates && wantAcceleration, pose);
    }
    lane.newtonIterations += out.iterations;
    lane.newtonResidual = std::max(lane.newtonResidual, out.residual);
    if (out.status == NewtonStatus::NoConvergence) {
      lane.report = {PoseStatus::NotAssemblable, PointId{first}, AssemblyFailure::NoConvergence};
      return false;
    }
    if (out.status == NewtonStatus::Singular) markSingular(lane, first);
    return true;
  }

  void ground(Lane& lane, std::size_t i, const GroundPoint& g) const {
    Pose& pose = *lane.pose;
    pose.position[i] = g.position;
    if (wantVelocity) pose.velocity[i].setZero();
    if (wantAcceleration) pose.acceleration[i].setZero();
  }

  void crank(Lane& lane, std::size_t i, const CrankPoint& c) const {
    const DriverState& driver = *lane.driver;
    Pose& pose = *lane.pose;
    const double phi = driver.position + c.phase;
    const Eigen::Vector2d radial(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d o = pose.position[c.pivot.index];
    pose.position[i] = o + c.length * radial;
    if (wantVelocity) pose.velocity[i] = c.length * driver.velocity * perp(radial);
    if (wantAcceleration)
      pose.acceleration[i] =
          c.length * (driver.acceleration * perp(radial) - driver.velocity * driver.velocity * radial);
  }

  // The driven point on its path: v = ṡ·p'(s), a = s̈·p'(s) + ṡ²·p''(s) (path_shape.h).
  void onPath(Lane& lane, std::size_t i, const PathPoint& d) const {
    const DriverState& driver = *lane.driver;
    Pose& pose = *lane.pose;
    const PathState at = pathAt(d.path, driver.position);
    pose.position[i] = at.point;
    if (wantVelocity) pose.velocity[i] = driver.velocity * at.tangent;
    if (wantAcceleration)
      pose.acceleration[i] = driver.acceleration * at.tangent + driver.velocity * driver.velocity * at.curvature;
  }

  // The actuator's end: an RRR dyad whose second length is the input q. Differentiating
  // |C − base|² = q² adds q·q̇ to the velocity row and q̇² + q·q̈ to the acceleration row.
  bool actuator(Lane& lane, std::size_t i, const ActuatorPoint& a) const {
    const DriverState& driver = *lane.driver;
    Pose& pose = *lane.pose;
    const double q = driver.position;
    const RrrCandidates cand =
        q > 0.0 ? rrrCandidates(pose.position[a.first.index], a.length, pose.position[a.base.index], q)
                : RrrCandidates{AssemblyFailure::TooClose};
    if (cand.failure != AssemblyFailure::None) {
      lane.report = {PoseStatus::NotAssemblable, PointId{i}, cand.failure};
      return false;
    }
    const signed char sign = chooseSign(i, a.branch, cand.open, cand.crossed);
    const Eigen::Vector2d c = sign > 0 ? cand.open : cand.crossed;
    pose.position[i] = c;
    pose.assemblyGap[i] = std::min(a.length + q - cand.distance, cand.distance - std::abs(a.length - q));
    pose.branchSign[i] = sign;
    const Eigen::Vector2d r1 = c - pose.position[a.first.index];
    const Eigen::Vector2d r2 = c - pose.position[a.base.index];
    if (wantTransmission) pose.transmissionAngle[i] = std::atan2(std::abs(cross(r1, r2)), r1.dot(r2));
    if (!wantVelocity || !lane.ratesValid) return true;
    double inverse = 0.0;
    if (!rrrInverseDeterminant(r1, r2, a.length * q, inverse)) {
      markSingular(lane, i);
      return true;
    }
    const Eigen::Vector2d& v1 = pose.velocity[a.first.index];
    const Eigen::Vector2d& vb = pose.velocity[a.base.index];
    const Eigen::Vector2d v = rrrSolve(r1, r2, inverse, {r1.dot(v1), r2.dot(vb) + q * driver.velocity});
    pose.velocity[i] = v;
    if (!wantAcceleration) return true;
    pose.acceleration[i] = rrrSolve(r1, r2, inverse,
                                    {r1.dot(pose.acceleration[a.first.index]) - (v - v1).squaredNorm(),
                                     r2.dot(pose.acceleration[a.base.index]) - (v - vb).squaredNorm() +
                                         driver.velocity * driver.velocity + q * driver.acceleration});
    return true;
  }

  // +1 for the open candidate, −1 for the crossed one: the predicted position decides if
  // given, else the tracked sign, else the mechanism's branch.
  signed char chooseSign(std::size_t i, Branch branch, const Eigen::Vector2d& open,
                         const Eigen::Vector2d& crossed) const {
    if (!guide.predicted.empty()) {
      const Eigen::Vector2d& target = guide.predicted[i];
      return (open - target).squaredNorm() <= (crossed - target).squaredNorm() ? 1 : -1;
    }
    if (!guide.signs.empty() && guide.signs[i] != 0) return guide.signs[i];
    return branch == Branch::Open ? 1 : -1;
  }

  // An RRR dyad in every live lane, in two passes: first both candidates in every lane (two
  // square roots and a division each, a chain the processor can overlap only across lanes), then
  // the choice and the rates. One pass per lane would leave each lane's chain waiting on itself.
  void pointInLanes(std::size_t i, const RrrPoint& r) {
    std::array<RrrCandidates, kMaxBlock> cand;
    for (std::size_t b = 0; b < live; ++b) {
      const Pose& pose = *lanes[b].pose;
      cand[b] =
          rrrCandidates(pose.position[r.first.index], r.firstLength, pose.position[r.second.index], r.secondLength);
      if (cand[b].failure != AssemblyFailure::None) {
        lanes[b].report = {PoseStatus::NotAssemblable, PointId{i}, cand[b].failure};
        live = b;
      }
    }
    for (std::size_t b = 0; b < live; ++b) rrr(lanes[b], i, r, cand[b]);
  }

  void rrr(Lane& lane, std::size_t i, const RrrPoint& r, const RrrCandidates& cand) const {
    Pose& pose = *lane.pose;
    const Eigen::Vector2d& p1 = pose.position[r.first.index];
    const Eigen::Vector2d& p2 = pose.position[r.second.index];
    const signed char sign = chooseSign(i, r.branch, cand.open, cand.crossed);
    const Eigen::Vector2d c = sign > 0 ? cand.open : cand.crossed;
    pose.position[i] = c;
    pose.assemblyGap[i] = std::min(r.firstLength + r.secondLength - cand.distance,
                                   cand.distance - std::abs(r.firstLength - r.secondLength));
    pose.branchSign[i] = sign;
    const Eigen::Vector2d r1 = c - p1;
    const Eigen::Vector2d r2 = c - p2;
    if (wantTransmission) pose.transmissionAngle[i] = std::atan2(std::abs(cross(r1, r2)), r1.dot(r2));
    if (!wantVelocity || !lane.ratesValid) return;
    // |r1|·|r2| is l1·l2 up to round-off: no square roots for the singularity test.
    double inverse = 0.0;
    if (!rrrInverseDeterminant(r1, r2, r.firstLength * r.secondLength, inverse)) {
      markSingular(lane, i);
      return;
    }
    const Eigen::Vector2d& v1 = pose.velocity[r.first.index];
    const Eigen::Vector2d& v2 = pose.velocity[r.second.index];
    const Eigen::Vector2d v = rrrSolve(r1, r2, inverse, {r1.dot(v1), r2.dot(v2)});
    pose.velocity[i] = v;
    if (!wantAcceleration) return;
    pose.acceleration[i] = rrrSolve(r1, r2, inverse,
                                    {r1.dot(pose.acceleration[r.first.index]) - (v - v1).squaredNorm(),
                                     r2.dot(pose.acceleration[r.second.index]) - (v - v2).squaredNorm()});
  }

  // A guide on a link needs that link's angle and rates first (its ends are solved already).
  GuideLine guideLine(Lane& lane, const Guide& g) const {
    Pose& pose = *lane.pose;
    if (g.link) link(lane, *g.link, crankPhaseOf(m, *g.link));
    return guideLineAt(m, g, pose);
  }

  bool rrp(Lane& lane, std::size_t i, const RrpPoint& p) const {
    Pose& pose = *lane.pose;
    const Eigen::Vector2d& p1 = pose.position[p.first.index];
    const GuideLine line = guideLine(lane, p.guide);
    const Eigen::Vector2d& u = line.direction;
    const RrpCandidates cand = rrpCandidates(p1, p.length, line.point, u);
    if (cand.failure != AssemblyFailure::None) {
      lane.report = {PoseStatus::NotAssemblable, PointId{i}, cand.failure};
      return false;
    }
    const Eigen::Vector2d open = line.point + cand.open * u;
    const Eigen::Vector2d crossed = line.point + cand.crossed * u;
    const signed char sign = chooseSign(i, p.branch, open, crossed);
    const Eigen::Vector2d c = sign > 0 ? open : crossed;
    pose.position[i] = c;
    pose.assemblyGap[i] = cand.reachGap;
    pose.branchSign[i] = sign;
    const Eigen::Vector2d r = c - p1;
    // 90° with the rod along the guide (the best), 0° with it across (the toggle).
    if (wantTransmission) pose.transmissionAngle[i] = std::atan2(std::abs(r.dot(u)), std::abs(cross(u, r)));
    if (!wantVelocity || !lane.ratesValid) return true;
    if (p.guide.link) return movingGuideRates(lane, i, p, line, r);
    const Eigen::Vector2d& v1 = pose.velocity[p.first.index];
    double sDot = 0.0;
    if (!rrpSolveRate(r, u, r.dot(v1), sDot)) {
      markSingular(lane, i);
      return true;
    }
    pose.velocity[i] = sDot * u;
    if (!wantAcceleration) return true;
    double sDdot = 0.0;
    rrpSolveRate(r, u, r.dot(pose.acceleration[p.first.index]) - (pose.velocity[i] - v1).squaredNorm(), sDdot);
    pose.acceleration[i] = sDdot * u;
    return true;
  }

  // A slider on a moving guide: the rod's r·(vC − v1) = 0 and the guide's row (guide_line.h),
  // the same 2×2 matrix [r; n] for velocity and acceleration (singular with the rod across).
  bool movingGuideRates(Lane& lane, std::size_t i, const RrpPoint& p, const GuideLine& line,
                        const Eigen::Vector2d& r) const {
    Pose& pose = *lane.pose;
    const Eigen::Vector2d n = guideNormal(line);
    const Eigen::Vector2d& c = pose.position[i];
    const Eigen::Vector2d& v1 = pose.velocity[p.first.index];
    Eigen::Vector2d v;
    if (!rrrSolveRates(r, n, {r.dot(v1), guideVelocityRhs(m, p.guide, line, pose, c)}, v)) {
      markSingular(lane, i);
      return true;
    }
    pose.velocity[i] = v;
    if (!wantAcceleration) return true;
    const Eigen::Vector2d rhs(r.dot(pose.acceleration[p.first.index]) - (v - v1).squaredNorm(),
                              guideAccelerationRhs(m, p.guide, line, pose, c, v));
    rrrSolveRates(r, n, rhs, pose.acceleration[i]);
    return true;
  }

  // Two sliders pinned together: C = G1 + s·u1 on both lines, s = ((G2 − G1)×u2)/(u1×u2). The
  // rates solve the two guides' rows [n1; n2] (guide_line.h), singular as the guides turn parallel.
  bool prp(Lane& lane, std::size_t i, const PrpPoint& p) const {
    Pose& pose = *lane.pose;
    const GuideLine l1 = guideLine(lane, p.first);
    const GuideLine l2 = guideLine(lane, p.second);
    const double sine = cross(l1.direction, l2.direction);
    if (!(std::abs(sine) > kSingularSine * kSingularSine)) {
      lane.report = {PoseStatus::NotAssemblable, PointId{i}, AssemblyFailure::Parallel};
      return false;
    }
    const Eigen::Vector2d c = l1.point + cross(l2.point - l1.point, l2.direction) / sine * l1.direction;
    pose.position[i] = c;
    if (wantTransmission) pose.transmissionAngle[i] = std::atan2(std::abs(sine), l1.direction.dot(l2.direction));
    if (!wantVelocity || !lane.ratesValid) return true;
    const Eigen::Vector2d n1 = guideNormal(l1);
    const Eigen::Vector2d n2 = guideNormal(l2);
    Eigen::Vector2d v;
    if (!rrrSolveRates(n1, n2, {guideVelocityRhs(m, p.first, l1, pose, c), guideVelocityRhs(m, p.second, l2, pose, c)},
                       v)) {
      markSingular(lane, i);
      return true;
    }
    pose.velocity[i] = v;
    if (!wantAcceleration) return true;
    const Eigen::Vector2d rhs(guideAccelerationRhs(m, p.first, l1, pose, c, v),
                              guideAccelerationRhs(m, p.second, l2, pose, c, v));
    rrrSolveRates(n1, n2, rhs, pose.acceleration[i]);
    return true;
  }

  // The slotted link's tip: D = O + l·e with e = r/|r|, r = P − O (derivation in rpr_point
  // terms: the slot's angle φ has φ̇ = r×ṙ/|r|² and φ̈ = r×r̈/|r|² − 2φ̇(r·ṙ)/|r|²).
  bool rpr(Lane& lane, std::size_t i, const RprPoint& s) const {
    Pose& pose = *lane.pose;
    const Eigen::Vector2d& o = pose.position[s.pivot.index];
    const Eigen::Vector2d r = pose.position[s.through.index] - o;
    const double r2 = r.squaredNorm();
    if (!(r2 > 0.0)) {
      lane.report = {PoseStatus::NotAssemblable, PointId{i}, AssemblyFailure::Coincident};
      return false;
    }
    const double len = std::sqrt(r2);
    const Eigen::Vector2d e = r / len;
    pose.position[i] = o + s.length * e;
    if (!wantVelocity || !lane.ratesValid) return true;
    const Eigen::Vector2d rDot = pose.velocity[s.through.index] - pose.velocity[s.pivot.index];
    const double phiDot = cross(r, rDot) / r2;
    pose.velocity[i] = pose.velocity[s.pivot.index] + s.length * phiDot * perp(e);
    if (!wantAcceleration) return true;
    const Eigen::Vector2d rDdot = pose.acceleration[s.through.index] - pose.acceleration[s.pivot.index];
    const double phiDdot = cross(r, rDdot) / r2 - 2.0 * phiDot * r.dot(rDot) / r2;
    pose.acceleration[i] = pose.acceleration[s.pivot.index] + s.length * (phiDdot * perp(e) - phiDot * phiDot * e);
    return true;
  }

  // The driven crank's angle and rates are the driver's, exactly (no atan2, and not a
  // difference of two velocities).
  void link(Lane& lane, LinkId id, std::optional<double> crankPhase) const {
    if (crankPhase) return crankLink(lane, id.index, *crankPhase);
    linkAngle(lane, id.index);
    linkRates(lane, id.index);
  }

  void crankLink(Lane& lane, std::size_t k, double phase) const {
    const DriverState& driver = *lane.driver;
    Pose& pose = *lane.pose;
    pose.linkAngle[k] = wrapAngle(driver.position + phase);
    if (wantVelocity) pose.linkOmega[k] = driver.velocity;
    if (wantAcceleration) pose.linkAlpha[k] = driver.acceleration;
  }

  void linkAngle(Lane& lane, std::size_t k) const {
    Pose& pose = *lane.pose;
    const Link& l = m.links[k];
    const Eigen::Vector2d r = pose.position[l.second.index] - pose.position[l.first.index];
    pose.linkAngle[k] = std::atan2(r.y(), r.x());
  }

  void linkRates(Lane& lane, std::size_t k) const {
    if (!lane.ratesValid || !wantVelocity) return;
    Pose& pose = *lane.pose;
    const Link& l = m.links[k];
    const Eigen::Vector2d r = pose.position[l.second.index] - pose.position[l.first.index];
    const double inverse = 1.0 / r.squaredNorm();
    pose.linkOmega[k] = cross(r, pose.velocity[l.second.index] - pose.velocity[l.first.index]) * inverse;
    if (wantAcceleration)
      pose.linkAlpha[k] = cross(r, pose.acceleration[l.second.index] - pose.acceleration[l.first.index]) * inverse;
  }

  void attached(Lane& lane, std::size_t i, const AttachedPoint& a) const {
    Pose& pose = *lane.pose;
    const std::size_t k = a.link.index;
    link(lane, a.link, crankPhaseOf(m, a.link));  // its ends are solved already; its rates may not be yet
    const Link& l = m.links[k];
    const Eigen::Vector2d base = pose.position[l.first.index];
    const Eigen::Vector2d u(std::cos(pose.linkAngle[k]), std::sin(pose.linkAngle[k]));
    const Eigen::Vector2d offset = a.along * u + a.across * perp(u);
    pose.position[i] = base + offset;
    if (!lane.ratesValid) return;
    const double w = pose.linkOmega[k];
    if (wantVelocity) pose.velocity[i] = pose.velocity[l.first.index] + w * perp(offset);
    if (wantAcceleration)
      pose.acceleration[i] = pose.acceleration[l.first.index] + pose.linkAlpha[k] * perp(offset) - w * w * offset;
  }

  // Point i, defined by `def`, in one lane (a free point: its whole group). False if it cannot
  // be assembled there.
  bool solve(Lane& lane, std::size_t i, const GroundPoint& g) const {
    ground(lane, i, g);
    return true;
  }
  bool solve(Lane& lane, std::size_t i, const CrankPoint& c) const {
    crank(lane, i, c);
    return true;
  }
  bool solve(Lane& lane, std::size_t i, const PathPoint& d) const {
    onPath(lane, i, d);
    return true;
  }
  bool solve(Lane& lane, std::size_t i, const ActuatorPoint& a) const { return actuator(lane, i, a); }
  bool solve(Lane& lane, std::size_t i, const RrpPoint& p) const { return rrp(lane, i, p); }
  bool solve(Lane& lane, std::size_t i, const RprPoint& s) const { return rpr(lane, i, s); }
  bool solve(Lane& lane, std::size_t i, const PrpPoint& q) const { return prp(lane, i, q); }
  bool solve(Lane& lane, std::size_t i, const FreePoint&) const { return freeGroup(lane, i, freeGroupEnd(m, i)); }
  bool solve(Lane& lane, std::size_t i, const AttachedPoint& a) const {
    attached(lane, i, a);
    return true;
  }

  // Point i in every live lane. A lane that cannot be assembled stops the block there: a sweep
  // keeps no pose after a failed one, so the lanes after it are not solved at all.
  void point(std::size_t i) {
    std::visit([&](const auto& def) { pointInLanes(i, def); }, m.points[i].definition);
  }

  template <typename Definition>
  void pointInLanes(std::size_t i, const Definition& def) {
    for (std::size_t b = 0; b < live; ++b) {
      if (!solve(lanes[b], i, def)) {
        live = b;
        return;
      }
    }
  }

  // A link in every live lane. The rates go first, all lanes together: with no library call
  // among them their values stay in registers; then the angles, one atan2 per lane.
  void link(LinkId id, std::optional<double> crankPhase) {
    if (crankPhase) {
      for (std::size_t b = 0; b < live; ++b) crankLink(lanes[b], id.index, *crankPhase);
      return;
    }
    for (std::size_t b = 0; b < live; ++b) linkRates(lanes[b], id.index);
    for (std::size_t b = 0; b < live; ++b) linkAngle(lanes[b], id.index);
  }

  // Everything, in the mechanism's order; or the scope's lists, made once per sweep. Returns
  // how many lanes were solved: all of them, or up to and including the first that failed.
  std::size_t run(const SolveScope* scope) {
    const std::size_t all = live;
    if (scope != nullptr) {
      for (const PointId p : scope->pointSteps) point(p.index);
      for (const LinkStep& l : scope->linkSteps) link(l.link, l.crankPhase);
    } else {
      for (std::size_t i = 0; i < m.points.size(); ++i) {
        point(i);
        if (isFreePoint(m, PointId{i})) i = freeGroupEnd(m, i) - 1;
      }
      for (std::size_t k = 0; k < m.links.size(); ++k) link(LinkId{k}, crankPhaseOf(m, LinkId{k}));
    }
    const std::size_t solved = live < all ? live + 1 : all;
    for (std::size_t b = 0; b < solved; ++b) {
      Lane& lane = lanes[b];
      lane.report.iterations = lane.newtonIterations;
      lane.report.residual = lane.newtonResidual;
      lane.pose->assembled = lane.report.status != PoseStatus::NotAssemblable;
    }
    return solved;
  }
};

std::string lengthName(const Mechanism& m, PointId a, PointId b, const std::string& fallback) {
  for (const Link& l : m.links)
    if ((l.first == a && l.second == b) || (l.first == b && l.second == a)) return l.name;
  return fallback;
}

// A failed or singular group of free points: its names, Newton's numbers, and the constraint
// left furthest from closing (solvespace's "culprit constraints", here the worst one).
std::string describeFreeGroup(const Mechanism& m, const PoseReport& report, const Pose& pose, const std::string& at) {
  const std::size_t first = report.culprit.index;
  const std::size_t last = freeGroupEnd(m, first);
  std::string names;
  for (std::size_t i = first; i < last; ++i) names += (i == first ? "" : ", ") + m.points[i].name;
  const bool several = last - first > 1;
  if (report.status == PoseStatus::Singular)
    return names + (several ? " are" : " is") + " at a singular position" + at + ": " + (several ? "their" : "its") +
           " distance constraints do not fix " + (several ? "their" : "its") +
           " motion (the linkage could move with the crank held, or a link is at a toggle), so velocity and "
           "acceleration are undefined there";
  const DistanceConstraint* worst = nullptr;
  for (const DistanceConstraint& c : m.constraints) {
    const std::size_t later = constraintLaterPoint(c).index;
    if (later < first || later >= last) continue;
    if (worst == nullptr || std::abs(constraintMisfit(c, pose)) > std::abs(constraintMisfit(*worst, pose))) worst = &c;
  }
  std::string where;
  if (worst != nullptr) {
    const std::string ends = m.points[worst->first.index].name + "–" + m.points[worst->second.index].name;
    const std::string link = lengthName(m, worst->first, worst->second, "");
    where = ", worst at " + (link.empty() ? ends : link + " " + ends);
  }
  return names + " cannot be assembled" + at + ": Newton did not converge (residual " +
         kinematics::formatShort(report.residual, 3) + " " + m.lengthUnit + " after " +
         std::to_string(report.iterations) + " iterations" + where + "); the linkage probably cannot close here";
}

// An actuator that cannot reach or is at a toggle: the dyad's sentence, with the actuator's
// length in place of a link.
std::string describeActuator(const Mechanism& m, const PoseReport& report, const Pose& pose, const ActuatorPoint& a,
                             double q, const std::string& at) {
  const std::string& name = m.points[report.culprit.index].name;
  const std::string& n1 = m.points[a.first.index].name;
  const std::string& base = m.points[a.base.index].name;
  const std::string len1 = lengthName(m, report.culprit, a.first, "first length");
  const std::string unit = " " + m.lengthUnit;
  if (report.status == PoseStatus::Singular)
    return name + " is at a toggle position" + at + ": " + len1 + " and the actuator " + base + "–" + name +
           " are collinear, so the actuator cannot move it there";
  if (!(q > 0.0)) return name + " cannot be placed" + at + ": an actuator's length must be positive";
  const double apart = (pose.position[a.base.index] - pose.position[a.first.index]).norm();
  const std::string gap = n1 + " and " + base + " are " + kinematics::formatShort(apart) + unit + " apart, ";
  if (report.failure == AssemblyFailure::TooFar)
    return name + " cannot be assembled" + at + ": " + gap + "more than " + len1 +
           " + actuator = " + kinematics::formatShort(a.length + q) + unit;
  if (report.failure == AssemblyFailure::TooClose)
    return name + " cannot be assembled" + at + ": " + gap + "less than |" + len1 +
           " − actuator| = " + kinematics::formatShort(std::abs(a.length - q)) + unit;
  return name + " cannot be assembled" + at + ": " + n1 + " and " + base + " coincide, so " + name + " is undetermined";
}

}  // namespace

void preparePose(const Mechanism& m, Pose& pose) {
  const std::size_t n = m.points.size();
  const std::size_t k = m.links.size();
  pose.position.assign(n, Eigen::Vector2d::Zero());
  pose.velocity.assign(n, Eigen::Vector2d::Zero());
  pose.acceleration.assign(n, Eigen::Vector2d::Zero());
  pose.transmissionAngle.assign(n, 0.0);
  pose.assemblyGap.assign(n, 0.0);
  pose.branchSign.assign(n, 0);
  pose.linkAngle.assign(k, 0.0);
  pose.linkOmega.assign(k, 0.0);
  pose.linkAlpha.assign(k, 0.0);
  pose.assembled = false;
  for (std::size_t i = 0; i < n; ++i)
    if (const auto* g = std::get_if<GroundPoint>(&m.points[i].definition)) pose.position[i] = g->position;
}

namespace {

Solver solverFor(const Mechanism& m, const SolveRequest& request, const BranchGuide& guide, std::span<Lane> lanes) {
  const bool acc = request.accelerations;
  return Solver{m, request.velocities || acc, acc, request.transmissionAngles, request.newton, guide, lanes};
}

}  // namespace

PoseReport solvePoseInto(const Mechanism& m, const DriverState& driver, const SolveRequest& request, Pose& pose,
                         const BranchGuide& guide, const SolveScope* scope) {
  Lane lane{&driver, &pose};
  solverFor(m, request, guide, {&lane, 1}).run(scope);
  return lane.report;
}

std::size_t solveBlockInto(const Mechanism& m, std::span<const DriverState> drivers, const SolveRequest& request,
                           std::span<Pose* const> poses, const BranchGuide& guide, const SolveScope& scope,
                           std::span<PoseReport> reports) {
  const std::size_t n = std::min(drivers.size(), kMaxBlock);
  std::array<Lane, kMaxBlock> lanes;
  for (std::size_t b = 0; b < n; ++b) lanes[b] = Lane{&drivers[b], poses[b]};
  const std::size_t solved = solverFor(m, request, guide, {lanes.data(), n}).run(&scope);
  for (std::size_t b = 0; b < solved; ++b) reports[b] = lanes[b].report;
  return solved;
}

Result<Pose> solvePose(const Mechanism& m, const DriverState& driver, const SolveRequest& request) {
  if (auto e = checkMechanism(m)) return *e;
  const InputKind kind = inputKind(m);
  const InputDomain d = inputDomain(kind);
  const bool angle = kind == InputKind::Angle;
  if (auto e = checkMagnitude(driver.position, angle ? "input angle" : "input position", d.position, d.positionUnit))
    return *e;
  if (auto e = checkMagnitude(driver.velocity, angle ? "input omega" : d.rateName, d.rate, d.rateUnit)) return *e;
  if (auto e = checkMagnitude(driver.acceleration, angle ? "input alpha" : d.accelerationName, d.acceleration,
                              d.accelerationUnit))
    return *e;
  if (auto e = checkNewtonSettings(request.newton)) return *e;
  Pose pose;
  preparePose(m, pose);
  const PoseReport report = solvePoseInto(m, driver, request, pose);
  if (report.status == PoseStatus::Ok) return pose;
  const ErrorCode code = report.status == PoseStatus::Singular ? ErrorCode::Singular : ErrorCode::NotAssemblable;
  return Error{code, m.points[report.culprit.index].name, describeFailure(m, report, pose, driver.position)};
}

std::string describeFailure(const Mechanism& m, const PoseReport& report, const Pose& pose, double inputAngle) {
  const std::size_t i = report.culprit.index;
  const std::string& name = m.points[i].name;
  const std::string unit = inputUnit(m);
  const std::string at = " at " + inputName(m) + " " + kinematics::formatShort(inputDisplayValue(m, inputAngle)) +
                         (unit == "°" ? unit : " " + unit);
  if (std::holds_alternative<FreePoint>(m.points[i].definition) && report.status != PoseStatus::Ok)
    return describeFreeGroup(m, report, pose, at);
  if (const auto* p = std::get_if<RrpPoint>(&m.points[i].definition); p != nullptr && report.status != PoseStatus::Ok) {
    const std::string rod = lengthName(m, report.culprit, p->first, "rod");
    const std::string& n1 = m.points[p->first.index].name;
    if (report.status == PoseStatus::Singular)
      return name + " is at a toggle position" + at + ": the " + rod +
             " is at right angles to the guide, so velocity and acceleration are undefined there";
    const GuideLine line = guideLineAt(m, p->guide, pose);
    const double distance = std::abs(cross(line.direction, line.point - pose.position[p->first.index]));
    return name + " cannot be assembled" + at + ": " + n1 + " is " + kinematics::formatShort(distance) + " " +
           m.lengthUnit + " from the guide, more than the " + rod + " length " + kinematics::formatShort(p->length) +
           " " + m.lengthUnit;
  }
  if (std::holds_alternative<PrpPoint>(m.points[i].definition) && report.status != PoseStatus::Ok)
    return name + (report.status == PoseStatus::Singular ? " is at a toggle position" : " cannot be assembled") + at +
           ": its two guides are parallel, so the sliders' pin is undetermined";
  if (const auto* s = std::get_if<RprPoint>(&m.points[i].definition);
      s != nullptr && report.status == PoseStatus::NotAssemblable)
    return name + " cannot be placed" + at + ": " + m.points[s->through.index].name + " lies on the pivot " +
           m.points[s->pivot.index].name + ", so the slot's direction is undetermined";
  if (const auto* a = std::get_if<ActuatorPoint>(&m.points[i].definition);
      a != nullptr && report.status != PoseStatus::Ok)
    return describeActuator(m, report, pose, *a, inputAngle, at);
  const auto* r = std::get_if<RrrPoint>(&m.points[i].definition);
  if (report.status == PoseStatus::Ok || r == nullptr) return name + " solved" + at;
  const std::string& n1 = m.points[r->first.index].name;
  const std::string& n2 = m.points[r->second.index].name;
  const std::string len1 = lengthName(m, report.culprit, r->first, "first length");
  const std::string len2 = lengthName(m, report.culprit, r->second, "second length");
  if (report.status == PoseStatus::Singular)
    return name + " is at a toggle position" + at + ": " + len1 + " and " + len2 +
           " are collinear, so angular velocity and acceleration are undefined there";
  const double apart = (pose.position[r->second.index] - pose.position[r->first.index]).norm();
  const std::string gap =
      n1 + " and " + n2 + " are " + kinematics::formatShort(apart) + " " + m.lengthUnit + " apart, ";
  switch (report.failure) {
  case AssemblyFailure::TooFar:
    return name + " cannot be assembled" + at + ": " + gap + "more than " + len1 + " + " + len2 + " = " +
           kinematics::formatShort(r->firstLength + r->secondLength) + " " + m.lengthUnit;
  case AssemblyFailure::TooClose:
    return name + " cannot be assembled" + at + ": " + gap + "less than |" + len1 + " − " + len2 +
           "| = " + kinematics::formatShort(std::abs(r->firstLength - r->secondLength)) + " " + m.lengthUnit;
  case AssemblyFailure::Coincident:
  case AssemblyFailure::Parallel:
  case AssemblyFailure::NoConvergence:
  case AssemblyFailure::None: break;
  }
  return name + " cannot be assembled" + at + ": " + n1 + " and " + n2 + " coincide, so " + name + " is undetermined";
}

}  // namespace linkwright::kinematics
