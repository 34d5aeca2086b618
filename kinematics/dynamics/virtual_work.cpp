#include "kinematics/dynamics/virtual_work.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/rigid_bodies.h"

#include <cmath>
#include <optional>
#include <utility>
#include <variant>

namespace linkwright::kinematics {
namespace {

// ω and α of the body a slider block turns with: its guide link's, or for a slotted link's
// block those of the line from the slotted link's pivot to its tip.
std::pair<double, double> blockRates(const Mechanism& m, const SliderKey& key, const Pose& p) {
  const PointDefinition& def = m.points[key.point.index].definition;
  std::optional<LinkId> link;
  if (const auto* rrp = std::get_if<RrpPoint>(&def)) link = rrp->guide.link;
  else if (const auto* q = std::get_if<PrpPoint>(&def)) link = (key.guide == 0 ? q->first : q->second).link;
  else if (const auto* s = std::get_if<RprPoint>(&def)) {
    const std::size_t tip = key.point.index, pivot = s->pivot.index;
    const Eigen::Vector2d r = p.position[tip] - p.position[pivot];
    return {cross(r, p.velocity[tip] - p.velocity[pivot]) / r.squaredNorm(),
            cross(r, p.acceleration[tip] - p.acceleration[pivot]) / r.squaredNorm()};
  }
  if (!link) return {0.0, 0.0};
  return {p.linkOmega[link->index], p.linkAlpha[link->index]};
}

PointId blockPin(const Mechanism& m, PointId point) {
  if (const auto* s = std::get_if<RprPoint>(&m.points[point.index].definition)) return s->through;
  return point;
}

// The virtual work with the velocities of `rates` times `perRate` (1/q̇ turns a moving pose's
// velocities into those per unit input rate without copying them).
VirtualWork scaledVirtualWork(const Mechanism& m, const LinkageDynamics& d, const Pose& motion, const Pose& rates,
                              double perRate) {
  const double s = *metresPerLengthUnit(m.lengthUnit);
  const Eigen::Vector2d g = d.loads.gravity.value_or(Eigen::Vector2d::Zero());
  VirtualWork w;
  const auto addMass = [&](double mass, double inertia, double omega, double alpha, const Eigen::Vector2d& v,
                           const Eigen::Vector2d& a) {
    const double translation = mass * a.dot(v), rotation = inertia * alpha * omega, weight = mass * g.dot(v);
    w.inertial += translation + rotation;
    w.gravity += weight;
    w.scale += std::abs(translation) + std::abs(rotation) + std::abs(weight);
  };
  for (const LinkMass& l : d.links) {
    const LinkId k = *m.findLink(l.link);
    const Link& link = m.links[k.index];
    const Eigen::Vector2d e = s * (motion.position[link.second.index] - motion.position[link.first.index]);
    const double length = e.norm();
    const Eigen::Vector2d u = e / length;
    const LinkFramePoint c = l.centre.value_or(LinkFramePoint{0.5 * length / s, 0.0});
    const Eigen::Vector2d r = s * (c.along * u + c.across * perp(u));
    const double omega = motion.linkOmega[k.index], alpha = motion.linkAlpha[k.index];
    const double unitOmega = perRate * rates.linkOmega[k.index];
    const Eigen::Vector2d v = s * perRate * rates.velocity[link.first.index] + unitOmega * perp(r);
    const Eigen::Vector2d a = s * motion.acceleration[link.first.index] + alpha * perp(r) - omega * omega * r;
    addMass(l.mass, l.inertia.value_or(l.mass * length * length / 12.0), unitOmega, alpha, v, a);
  }
  for (const SliderMass& sm : d.sliders) {
    const SliderKey key{*m.findPoint(sm.point), sm.guide};
    const PointId pin = blockPin(m, key.point);
    const double alpha = blockRates(m, key, motion).second;
    const double unitOmega = perRate * blockRates(m, key, rates).first;
    addMass(sm.mass, sm.inertia, unitOmega, alpha, s * perRate * rates.velocity[pin.index],
            s * motion.acceleration[pin.index]);
  }
  for (const LinkTorque& t : d.loads.torques) {
    const double work = t.torque * perRate * rates.linkOmega[m.findLink(t.link)->index];
    w.loads += work;
    w.scale += std::abs(work);
  }
  for (const PointForce& f : d.loads.forces) {
    const PointId at = f.link.empty() ? blockPin(m, *m.findPoint(f.point)) : *m.findPoint(f.point);
    const double work = f.force.dot(s * perRate * rates.velocity[at.index]);
    w.loads += work;
    w.scale += std::abs(work);
  }
  for (const Spring& sp : d.loads.springs) {
    const PointId a = *m.findPoint(sp.first.point), b = *m.findPoint(sp.second.point);
    const Eigen::Vector2d between = s * (motion.position[b.index] - motion.position[a.index]);
    const double length = between.norm();
    if (length == 0.0) continue;
    const Eigen::Vector2d pull = (sp.stiffness * (length - s * sp.freeLength) + sp.preload) * (between / length);
    const double work = pull.dot(s * perRate * (rates.velocity[a.index] - rates.velocity[b.index]));
    w.loads += work;
    w.scale += std::abs(work);
  }
  return w;
}

}  // namespace

VirtualWork virtualWork(const Mechanism& m, const LinkageDynamics& d, const Pose& motion, const Pose& rates) {
  return scaledVirtualWork(m, d, motion, rates, 1.0);
}

Result<CrankVirtualWork> CrankVirtualWork::create(const Mechanism& m, const LinkageDynamics& d) {
  if (inputKind(m) != InputKind::Angle || !driverPoint(m))
    return Error{ErrorCode::InvalidValue, "driver",
                 "the driving torque by virtual work is for a linkage driven by a crank (this one is driven by its " +
                     inputName(m) + ")"};
  const PointId tip = *driverPoint(m);
  return CrankVirtualWork(m, d, tip, std::get<CrankPoint>(m.points[tip.index].definition).pivot);
}

CrankVirtualWork::CrankVirtualWork(const Mechanism& m, const LinkageDynamics& d, PointId tip, PointId pivot)
    : m_mechanism(&m), m_dynamics(&d), m_tip(tip), m_pivot(pivot) {
  preparePose(m, m_rates);
}

double CrankVirtualWork::torque(const Pose& motion, double inputAngle) {
  const Eigen::Vector2d arm = motion.position[m_tip.index] - motion.position[m_pivot.index];
  const double rate = cross(arm, motion.velocity[m_tip.index] - motion.velocity[m_pivot.index]) / arm.squaredNorm();
  if (rate != 0.0) return scaledVirtualWork(*m_mechanism, *m_dynamics, motion, motion, 1.0 / rate).generalizedForce();
  BranchGuide guide;
  guide.predicted = motion.position;
  solvePoseInto(*m_mechanism, {inputAngle, 1.0, 0.0}, SolveRequest{true, false}, m_rates, guide);
  return virtualWork(*m_mechanism, *m_dynamics, motion, m_rates).generalizedForce();
}

}  // namespace linkwright::kinematics
