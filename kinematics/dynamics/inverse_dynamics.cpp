#include "kinematics/dynamics/inverse_dynamics.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace linkwright::kinematics {
namespace {

// First row of a moving body's three equations (the ground has none).
Eigen::Index rowOf(BodyId body) { return static_cast<Eigen::Index>(3 * (body.index - 1)); }

}  // namespace

Result<InverseDynamics> InverseDynamics::create(const Mechanism& mechanism, const LinkageDynamics& dynamics) {
  if (auto e = checkMechanism(mechanism)) return *e;
  if (auto e = checkDynamics(mechanism, dynamics)) return *e;
  const auto metres = metresPerLengthUnit(mechanism.lengthUnit);
  if (!metres)
    return Error{ErrorCode::InvalidValue, "lengthUnit",
                 "lengthUnit must be m, cm, mm, in or ft for forces, which need lengths in metres (got \"" +
                     mechanism.lengthUnit + "\")"};
  auto bodies = bodiesOf(mechanism);
  if (!bodies) return bodies.error();
  InverseDynamics id;
  id.m_mechanism = mechanism;
  id.m_bodies = std::move(*bodies);
  id.m_metres = *metres;
  if (auto e = id.resolve(dynamics)) return *e;
  const auto n = static_cast<Eigen::Index>(id.m_bodies.unknowns());
  const std::size_t bodyCount = id.m_bodies.bodies.size();
  id.m_omega.assign(bodyCount, 0.0);
  id.m_alpha.assign(bodyCount, 0.0);
  id.m_reference.assign(bodyCount, Eigen::Vector2d::Zero());
  id.m_load.assign(bodyCount, Eigen::Vector2d::Zero());
  id.m_loadMoment.assign(bodyCount, 0.0);
  id.m_prismaticNormal.assign(id.m_bodies.prismatics.size(), Eigen::Vector2d::Zero());
  for (const Body& b : id.m_bodies.bodies) {
    std::optional<LinkId> link;
    if (!b.links.empty()) link = b.links[0];
    std::optional<std::size_t> turnsWith;
    if (b.kind == BodyKind::Slider) turnsWith = b.turnsWith.index;
    id.m_rates.push_back({b.reference, b.second, link, turnsWith});
  }
  id.m_matrix.setZero(n, n);
  id.m_rhs.setZero(n);
  id.m_solution.setZero(n);
  id.m_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  id.planChain();
  return id;
}

// Names become ids and bodies; defaults are filled in: the midpoint, a uniform slender bar.
std::optional<Error> InverseDynamics::resolve(const LinkageDynamics& d) {
  const Mechanism& m = m_mechanism;
  for (const LinkMass& l : d.links) {
    const LinkId link = *m.findLink(l.link);
    const double length = linkLength(m, link);
    const double lengthMetres = length * m_metres;
    const LinkFramePoint centre = l.centre.value_or(LinkFramePoint{0.5 * length, 0.0});
    const double inertia = l.inertia.value_or(l.mass * lengthMetres * lengthMetres / 12.0);
    const Link& ends = m.links[link.index];
    m_masses.push_back({m_bodies.linkBody[link.index], link, l.mass, inertia, centre, ends.first, ends.second});
  }
  for (const SliderMass& s : d.sliders) {
    const BodyId block = *m_bodies.findSlider({*m.findPoint(s.point), s.guide});
    const PointId pin = m_bodies.bodies[block.index].reference;
    m_masses.push_back({block, std::nullopt, s.mass, s.inertia, {}, pin, pin});
  }
  for (const LinkTorque& t : d.loads.torques)
    m_torques.push_back({m_bodies.linkBody[m.findLink(t.link)->index], t.torque});
  for (const PointForce& f : d.loads.forces) {
    if (f.link.empty()) {
      const BodyId block = *m_bodies.findSlider({*m.findPoint(f.point), f.guide});
      m_forces.push_back({block, m_bodies.bodies[block.index].reference, f.force});
    } else {
      m_forces.push_back({m_bodies.linkBody[m.findLink(f.link)->index], *m.findPoint(f.point), f.force});
    }
  }
  const auto endBody = [&](const SpringEnd& end) {
    return end.link.empty() ? kGroundBody : m_bodies.linkBody[m.findLink(end.link)->index];
  };
  for (const Spring& sp : d.loads.springs) {
    const BodySpring spring{
        endBody(sp.first), *m.findPoint(sp.first.point), endBody(sp.second), *m.findPoint(sp.second.point),
        sp.stiffness,      sp.freeLength * m_metres,     sp.preload};
    // Between two points of one body (the frame's or a link's) a spring only strains it.
    if (spring.firstBody != spring.secondBody) m_springs.push_back(spring);
  }
  m_gravity = d.loads.gravity;
  // Loads on a link fixed to the ground go straight into the frame: nothing to solve for.
  std::erase_if(m_masses, [](const MassElement& e) { return e.body == kGroundBody; });
  std::erase_if(m_torques, [](const BodyTorque& t) { return t.body == kGroundBody; });
  std::erase_if(m_forces, [](const BodyForce& f) { return f.body == kGroundBody; });
  return std::nullopt;
}

void InverseDynamics::prepare(PoseForces& f) const {
  f.revolute.assign(m_bodies.revolutes.size(), Eigen::Vector2d::Zero());
  f.normal.assign(m_bodies.prismatics.size(), 0.0);
  f.moment.assign(m_bodies.prismatics.size(), 0.0);
  f.driveTorque = 0.0;
  f.driveAlong = 0.0;
  f.driveForce.setZero();
  f.jointTorque.setZero();
  f.shakingForce.setZero();
  f.shakingMoment = 0.0;
}

// Angular velocity and acceleration of every moving body: its first link's, else from two of
// its points; a block's are those of the body it slides on (blocks come after rigid bodies). And
// where its reference point is, which its moment equation is taken about.
void InverseDynamics::bodyRates(const Pose& pose) {
  for (std::size_t k = 1; k < m_bodies.bodies.size(); ++k) {
    const BodyRate& b = m_rates[k];
    m_reference[k] = at(pose, b.reference);
    if (b.turnsWith) {
      m_omega[k] = m_omega[*b.turnsWith];
      m_alpha[k] = m_alpha[*b.turnsWith];
    } else if (b.link) {
      m_omega[k] = pose.linkOmega[b.link->index];
      m_alpha[k] = pose.linkAlpha[b.link->index];
    } else {
      const std::size_t p = b.reference.index;
      const std::size_t q = b.second.index;
      const Eigen::Vector2d r = pose.position[q] - pose.position[p];
      m_omega[k] = cross(r, pose.velocity[q] - pose.velocity[p]) / r.squaredNorm();
      m_alpha[k] = cross(r, pose.acceleration[q] - pose.acceleration[p]) / r.squaredNorm();
    }
  }
}

// Every moving body's load, the right-hand side of its equations in SI: the inertia (and −m g)
// of its mass elements, external loads with their sign changed; the resultant and the moment
// about its reference point.
void InverseDynamics::bodyLoads(const Pose& pose) {
  std::fill(m_load.begin(), m_load.end(), Eigen::Vector2d::Zero());
  std::fill(m_loadMoment.begin(), m_loadMoment.end(), 0.0);
  const Eigen::Vector2d g = m_gravity.value_or(Eigen::Vector2d::Zero());
  for (const MassElement& e : m_masses) {
    const std::size_t k = e.body.index;
    const double w = m_omega[k];
    const double alpha = m_alpha[k];
    Eigen::Vector2d r = Eigen::Vector2d::Zero();  // from the body's reference point to the centre, m
    Eigen::Vector2d accel = m_metres * pose.acceleration[e.first.index];
    if (e.link) {
      // G − A = along·u + across·u⊥, u = d/|d| along the link, in metres.
      const Eigen::Vector2d d = pose.position[e.second.index] - pose.position[e.first.index];
      const Eigen::Vector2d c = (m_metres / d.norm()) * (e.centre.along * d + e.centre.across * perp(d));
      accel += alpha * perp(c) - w * w * c;
      r = (at(pose, e.first) - m_reference[k]) + c;
    }
    const Eigen::Vector2d inertiaForce = e.mass * (accel - g);
    m_load[k] += inertiaForce;
    m_loadMoment[k] += e.inertia * alpha + cross(r, inertiaForce);
  }
  for (const BodyTorque& t : m_torques) m_loadMoment[t.body.index] -= t.torque;
  for (const BodyForce& f : m_forces) {
    m_load[f.body.index] -= f.force;
    m_loadMoment[f.body.index] -= cross(at(pose, f.point) - m_reference[f.body.index], f.force);
  }
  for (const BodySpring& sp : m_springs) {
    const Eigen::Vector2d pull = springPull(pose, sp);
    for (const auto& [body, point, force] :
         {std::tuple{sp.firstBody, sp.first, pull}, {sp.secondBody, sp.second, -pull}}) {
      if (body == kGroundBody) continue;
      m_load[body.index] -= force;
      m_loadMoment[body.index] -= cross(at(pose, point) - m_reference[body.index], force);
    }
  }
}

// Tension k (L − L0) + preload along the line from the first end to the second; no direction,
// and so no force, when the ends meet.
Eigen::Vector2d InverseDynamics::springPull(const Pose& pose, const BodySpring& s) const {
  const Eigen::Vector2d d = at(pose, s.second) - at(pose, s.first);
  const double length = d.norm();
  if (length == 0.0) return Eigen::Vector2d::Zero();
  return (s.stiffness * (length - s.freeLength) + s.preload) * (d / length);
}

void InverseDynamics::prismaticNormals(const Pose& pose) {
  for (std::size_t j = 0; j < m_bodies.prismatics.size(); ++j)
    m_prismaticNormal[j] = perp(prismaticDirection(m_mechanism, m_bodies.prismatics[j], pose));
}

void InverseDynamics::addJoints(const Pose& pose) {
  const double L = m_scale;
  const auto& rev = m_bodies.revolutes;
  for (std::size_t j = 0; j < rev.size(); ++j) {
    const Eigen::Vector2d p = at(pose, rev[j].point);
    const auto c = static_cast<Eigen::Index>(2 * j);
    for (const auto& [body, sign] : {std::pair{rev[j].body, 1.0}, std::pair{rev[j].hub, -1.0}}) {
      if (body == kGroundBody) continue;
      const Eigen::Index row = rowOf(body);
      const Eigen::Vector2d r = p - m_reference[body.index];
      m_matrix(row, c) += sign;
      m_matrix(row + 1, c + 1) += sign;
      m_matrix(row + 2, c) -= sign * r.y() / L;
      m_matrix(row + 2, c + 1) += sign * r.x() / L;
    }
  }
  const auto& pri = m_bodies.prismatics;
  for (std::size_t j = 0; j < pri.size(); ++j) {
    const Eigen::Vector2d& n = m_prismaticNormal[j];
    const Eigen::Vector2d p = at(pose, pri[j].pin);
    const auto c = static_cast<Eigen::Index>(2 * (rev.size() + j));
    for (const auto& [body, sign] : {std::pair{pri[j].block, 1.0}, std::pair{pri[j].guide, -1.0}}) {
      if (body == kGroundBody) continue;
      const Eigen::Index row = rowOf(body);
      const Eigen::Vector2d r = p - m_reference[body.index];
      m_matrix(row, c) += sign * n.x();
      m_matrix(row + 1, c) += sign * n.y();
      m_matrix(row + 2, c) += sign * cross(r, n) / L;
      m_matrix(row + 2, c + 1) += sign;  // the couple M = L·x: its row and column scalings cancel
    }
  }
}

// A force of unit size along `direction` at `point` on `body`, times `sign`, per unit of the
// unknown in `column` (a force: no scaling, its moment row divided by L like every other).
void InverseDynamics::addForceColumn(BodyId body, const Eigen::Vector2d& point, const Eigen::Vector2d& direction,
                                     double sign, Eigen::Index column) {
  if (body == kGroundBody) return;
  const Eigen::Index row = rowOf(body);
  const Eigen::Vector2d r = point - m_reference[body.index];
  m_matrix(row, column) += sign * direction.x();
  m_matrix(row + 1, column) += sign * direction.y();
  m_matrix(row + 2, column) += sign * cross(r, direction) / m_scale;
}

// The driver's columns, after the joints' (rigid_bodies.h, header comment).
void InverseDynamics::addDrive(const Pose& pose) {
  const Drive& d = m_bodies.drive;
  const auto c = static_cast<Eigen::Index>(2 * (m_bodies.revolutes.size() + m_bodies.prismatics.size()));
  switch (d.kind) {
  case DriveKind::Crank: m_matrix(rowOf(d.body) + 2, c) += 1.0; break;  // T = L·x, as a couple M
  case DriveKind::Actuator: {
    const Eigen::Vector2d tip = at(pose, d.point);
    const Eigen::Vector2d base = at(pose, d.pivot);
    m_actuatorAxis = (tip - base).normalized();
    addForceColumn(d.body, tip, m_actuatorAxis, 1.0, c);
    addForceColumn(d.base, base, m_actuatorAxis, -1.0, c);
    break;
  }
  case DriveKind::Path: {
    const Eigen::Vector2d p = at(pose, d.point);
    addForceColumn(d.body, p, Eigen::Vector2d::UnitX(), 1.0, c);
    addForceColumn(d.body, p, Eigen::Vector2d::UnitY(), 1.0, c + 1);
    break;
  }
  }
}

// The whole scaled system: joints' and driver's columns, the loads on the right (moments / L).
void InverseDynamics::assemble(const Pose& pose) {
  const Eigen::Vector2d o = momentOrigin(pose);
  double size2 = 0.0;  // the largest squared distance: one square root, the same L
  for (const Eigen::Vector2d& p : pose.position) size2 = std::max(size2, (m_metres * p - o).squaredNorm());
  m_scale = size2 > 0.0 ? std::sqrt(size2) : 1.0;
  m_matrix.setZero();
  bodyRates(pose);
  bodyLoads(pose);
  prismaticNormals(pose);
  addJoints(pose);
  addDrive(pose);
  for (std::size_t k = 1; k < m_bodies.bodies.size(); ++k) {
    const Eigen::Index row = rowOf(BodyId{k});
    m_rhs(row) = m_load[k].x();
    m_rhs(row + 1) = m_load[k].y();
    m_rhs(row + 2) = m_loadMoment[k] / m_scale;
  }
}

Eigen::Vector2d InverseDynamics::momentOrigin(const Pose& pose) const {
  return m_bodies.momentPoint ? at(pose, *m_bodies.momentPoint) : Eigen::Vector2d::Zero();
}

void InverseDynamics::extract(const Pose& pose, std::optional<double> input, PoseForces& f) const {
  const Eigen::Vector2d o = momentOrigin(pose);
  f.shakingForce.setZero();
  f.shakingMoment = 0.0;
  const auto& rev = m_bodies.revolutes;
  for (std::size_t j = 0; j < rev.size(); ++j) {
    f.revolute[j] = m_solution.segment<2>(static_cast<Eigen::Index>(2 * j));
    if (rev[j].hub != kGroundBody) continue;
    f.shakingForce -= f.revolute[j];
    f.shakingMoment -= cross(at(pose, rev[j].point) - o, f.revolute[j]);
  }
  const auto& pri = m_bodies.prismatics;
  for (std::size_t j = 0; j < pri.size(); ++j) {
    const auto c = static_cast<Eigen::Index>(2 * (rev.size() + j));
    f.normal[j] = m_solution(c);
    f.moment[j] = m_solution(c + 1);
    if (pri[j].guide != kGroundBody) continue;
    const Eigen::Vector2d onBlock = f.normal[j] * m_prismaticNormal[j];
    f.shakingForce -= onBlock;
    f.shakingMoment -= cross(at(pose, pri[j].pin) - o, onBlock) + f.moment[j];
  }
  // A spring anchored on the frame pulls it too.
  for (const BodySpring& sp : m_springs)
    for (const auto& [body, point, force] : {std::tuple{sp.firstBody, sp.first, springPull(pose, sp)},
                                             {sp.secondBody, sp.second, -springPull(pose, sp)}}) {
      if (body != kGroundBody) continue;
      f.shakingForce += force;
      f.shakingMoment += cross(at(pose, point) - o, force);
    }
  extractDrive(pose, input, f);
}

// The driver's unknowns (after the joints'), its reaction on the frame and, for a serial arm,
// τ = JᵀF (header comment).
void InverseDynamics::extractDrive(const Pose& pose, std::optional<double> input, PoseForces& f) const {
  const Drive& d = m_bodies.drive;
  const auto c = static_cast<Eigen::Index>(2 * (m_bodies.revolutes.size() + m_bodies.prismatics.size()));
  const Eigen::Vector2d o = momentOrigin(pose);
  f.driveTorque = 0.0;
  f.driveAlong = 0.0;
  f.driveForce.setZero();
  f.jointTorque.setZero();
  switch (d.kind) {
  case DriveKind::Crank:
    f.driveTorque = m_solution(c);
    f.shakingMoment -= f.driveTorque;
    return;
  case DriveKind::Actuator:
    f.driveAlong = m_solution(c);
    f.driveForce = f.driveAlong * m_actuatorAxis;
    if (d.base != kGroundBody) return;
    f.shakingForce -= f.driveForce;
    f.shakingMoment -= cross(at(pose, d.pivot) - o, f.driveForce);
    return;
  case DriveKind::Path: {
    const Eigen::Vector2d p = at(pose, d.point);
    const PathShape& shape = std::get<PathPoint>(m_mechanism.points[d.point.index].definition).path;
    const double s = input ? *input : nearestPathCoordinate(shape, pose.position[d.point.index]);
    f.driveForce = m_solution.segment<2>(c);
    f.driveAlong = f.driveForce.dot(pathAt(shape, s).tangent);
    f.shakingForce -= f.driveForce;
    f.shakingMoment -= cross(p - o, f.driveForce);
    if (m_bodies.arm)
      f.jointTorque = Eigen::Vector2d(cross(p - at(pose, m_bodies.arm->pivot), f.driveForce),
                                      cross(p - at(pose, m_bodies.arm->elbow), f.driveForce));
    return;
  }
  }
}

PoseStatus InverseDynamics::solveInto(const Pose& pose, PoseForces& forces, std::optional<double> input) {
  if (m_chain.empty() || !solveLinkByLink(pose)) return solveByLuInto(pose, forces, input);
  m_lastMethod = Method::LinkByLink;
  extract(pose, input, forces);
  return PoseStatus::Ok;
}

PoseStatus InverseDynamics::solveByLuInto(const Pose& pose, PoseForces& forces, std::optional<double> input) {
  m_lastMethod = Method::Lu;
  assemble(pose);
  m_lu.compute(m_matrix);
  // The pivots of U, against the largest: below kForceRankThreshold the system is singular.
  const auto pivots = m_lu.matrixLU().diagonal().cwiseAbs();
  if (!(pivots.minCoeff() > kForceRankThreshold * pivots.maxCoeff())) {
    prepare(forces);
    return PoseStatus::Singular;
  }
  // x = U⁻¹·L⁻¹·P·b in the buffers sized at create(): no allocation per sample.
  m_solution.noalias() = m_lu.permutationP() * m_rhs;
  m_lu.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(m_solution);
  m_lu.matrixLU().triangularView<Eigen::Upper>().solveInPlace(m_solution);
  if (!m_solution.allFinite()) {
    prepare(forces);
    return PoseStatus::Singular;
  }
  // The couples were solved as M / L: back to N·m.
  const auto first = static_cast<Eigen::Index>(2 * m_bodies.revolutes.size());
  for (std::size_t j = 0; j < m_bodies.prismatics.size(); ++j) m_solution(first + 2 * j + 1) *= m_scale;
  if (m_bodies.drive.kind == DriveKind::Crank) m_solution(first + 2 * m_bodies.prismatics.size()) *= m_scale;
  extract(pose, input, forces);
  return PoseStatus::Ok;
}

Result<PoseForces> forcesAtPose(const Mechanism& mechanism, const LinkageDynamics& dynamics, const Pose& pose,
                                std::optional<double> input) {
  auto solver = InverseDynamics::create(mechanism, dynamics);
  if (!solver) return solver.error();
  InverseDynamics& solve = solver.value();
  PoseForces forces;
  solve.prepare(forces);
  if (solve.solveInto(pose, forces, input) != PoseStatus::Ok)
    return Error{ErrorCode::Singular, "pose",
                 "the joint forces are not determined at this pose: the Newton–Euler system is singular (a toggle "
                 "position, or links that lock each other)"};
  return forces;
}

}  // namespace linkwright::kinematics
