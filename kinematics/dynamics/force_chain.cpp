// InverseDynamics link by link (inverse_dynamics.h, "Link by link"): finding the order of
// closed-form groups once, and solving a pose by it.

#include "kinematics/dynamics/inverse_dynamics.h"

#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

// The link-by-link order (header comment): repeatedly the crank once it has only its pin and
// the torque left, else a dyad, until every body is solved. None if neither is found at some
// point, or if an unknown is of a kind the closed forms do not take (an actuator's force).
void InverseDynamics::planChain() {
  using Kind = ChainUnknown::Kind;
  const auto& rev = m_bodies.revolutes;
  const auto& pri = m_bodies.prismatics;
  for (std::size_t j = 0; j < rev.size(); ++j)
    m_unknowns.push_back({Kind::Pin, static_cast<Eigen::Index>(2 * j), rev[j].point, rev[j].body, rev[j].hub});
  for (std::size_t j = 0; j < pri.size(); ++j)
    m_unknowns.push_back(
        {Kind::Slide, static_cast<Eigen::Index>(2 * (rev.size() + j)), pri[j].pin, pri[j].block, pri[j].guide, j});
  const Drive& d = m_bodies.drive;
  const auto driveColumn = static_cast<Eigen::Index>(2 * (rev.size() + pri.size()));
  if (d.kind == DriveKind::Actuator) return;
  m_unknowns.push_back(
      {d.kind == DriveKind::Crank ? Kind::Torque : Kind::Pin, driveColumn, d.point, d.body, kGroundBody});

  std::vector<bool> known(m_unknowns.size(), false);
  std::vector<bool> solved(m_bodies.bodies.size(), false);
  const auto reaches = [&](std::size_t u, BodyId b) { return m_unknowns[u].body == b || m_unknowns[u].hub == b; };
  const auto open = [&](BodyId b) {
    std::vector<std::size_t> found;
    for (std::size_t u = 0; u < m_unknowns.size(); ++u)
      if (!known[u] && reaches(u, b)) found.push_back(u);
    return found;
  };
  const auto kind = [&](std::size_t u) { return m_unknowns[u].kind; };
  const auto add = [&](ChainStep step) {
    const auto in = [&](BodyId b) { return b == step.body[0] || (step.dyad && b == step.body[1]); };
    for (int i = 0; i < (step.dyad ? 3 : 2); ++i) {
      const std::size_t u = step.unknown[i];
      known[u] = true;
      for (const BodyId b : {m_unknowns[u].body, m_unknowns[u].hub})
        if (b != kGroundBody && !in(b)) step.passOn.emplace_back(u, b);
    }
    for (const BodyId b : step.body) solved[b.index] = true;
    m_chain.push_back(std::move(step));
  };

  std::size_t left = m_bodies.movingBodies();
  while (left > 0) {
    bool found = false;
    // The crank: its pin and the torque.
    for (std::size_t k = 1; k < m_bodies.bodies.size() && !found; ++k) {
      const BodyId b{k};
      const auto list = open(b);
      if (solved[k] || list.size() != 2) continue;
      const bool torqueFirst = kind(list[0]) == Kind::Torque;
      const std::size_t pin = torqueFirst ? list[1] : list[0];
      const std::size_t torque = torqueFirst ? list[0] : list[1];
      if (kind(pin) != Kind::Pin || kind(torque) != Kind::Torque) continue;
      add({false, {b, b}, {pin, torque, 0}, {}});
      left -= 1;
      found = true;
    }
    // A dyad: a pin between two bodies, each held by one more pin or slide.
    for (std::size_t k1 = 1; k1 < m_bodies.bodies.size() && !found; ++k1) {
      for (std::size_t k2 = k1 + 1; k2 < m_bodies.bodies.size() && !found; ++k2) {
        const BodyId b1{k1};
        const BodyId b2{k2};
        const auto list1 = open(b1);
        const auto list2 = open(b2);
        if (solved[k1] || solved[k2] || list1.size() != 2 || list2.size() != 2) continue;
        const auto shared = [&](std::size_t u) { return reaches(u, b1) && reaches(u, b2); };
        const std::size_t j = shared(list1[0]) ? list1[0] : list1[1];
        const std::size_t j1 = j == list1[0] ? list1[1] : list1[0];
        const std::size_t j2 = j == list2[0] ? list2[1] : list2[0];
        // An outer slide is the block's (its guide outside the dyad): the block holds one
        // point, its pin, where both joints act.
        const auto outer = [&](std::size_t u, BodyId b) {
          return !shared(u) && (kind(u) == Kind::Pin || (kind(u) == Kind::Slide && m_unknowns[u].body == b));
        };
        if (!shared(j) || kind(j) != Kind::Pin || (j != list2[0] && j != list2[1]) || !outer(j1, b1) || !outer(j2, b2))
          continue;
        add({true, {b1, b2}, {j1, j, j2}, {}});
        left -= 2;
        found = true;
      }
    }
    if (!found) {
      m_chain.clear();
      return;
    }
  }
}

// A solved unknown's force and couple on `body`, a later step's, moved into its load.
void InverseDynamics::passOn(const Pose& pose, const ChainUnknown& u, BodyId body) {
  const double sign = u.sign(body);
  const Eigen::Vector2d r = at(pose, u.point) - m_reference[body.index];
  Eigen::Vector2d force;
  double couple = 0.0;
  if (u.kind == ChainUnknown::Kind::Slide) {
    force = sign * m_solution(u.column) * m_prismaticNormal[u.slide];
    couple = sign * m_solution(u.column + 1);
  } else {
    force = sign * m_solution.segment<2>(u.column);
  }
  m_load[body.index] -= force;
  m_loadMoment[body.index] -= cross(r, force) + couple;
}

// A dyad in closed form (header comment). False, nothing decided, within kChainMargin of its
// toggle.
bool InverseDynamics::solveDyad(const Pose& pose, const ChainStep& step) {
  const ChainUnknown& pin = m_unknowns[step.unknown[1]];
  const Eigen::Vector2d q = at(pose, pin.point);
  std::array<Eigen::Vector2d, 2> row;
  std::array<double, 2> rhs{};
  std::array<Eigen::Vector2d, 2> point;
  for (int k = 0; k < 2; ++k) {
    const BodyId b = step.body[k];
    const ChainUnknown& outer = m_unknowns[step.unknown[2 * k]];
    const double sign = pin.sign(b);
    point[k] = at(pose, outer.point);
    if (outer.kind == ChainUnknown::Kind::Pin) {
      // Moments about the outer pin: (Q − P) × G = M − (P − O) × R.
      const Eigen::Vector2d w = q - point[k];
      row[k] = sign * Eigen::Vector2d(-w.y(), w.x());
      rhs[k] = m_loadMoment[b.index] - cross(point[k] - m_reference[b.index], m_load[b.index]);
    } else {
      // Forces along the slide u (n = u⊥, so u = −n⊥): G·u = R·u.
      const Eigen::Vector2d& n = m_prismaticNormal[outer.slide];
      const Eigen::Vector2d u(n.y(), -n.x());
      row[k] = sign * u;
      rhs[k] = m_load[b.index].dot(u);
    }
  }
  const double det = cross(row[0], row[1]);
  if (!(det * det > kChainMargin * kChainMargin * row[0].squaredNorm() * row[1].squaredNorm())) return false;
  // G: the pin's force on its body from its hub.
  const Eigen::Vector2d g =
      Eigen::Vector2d(rhs[0] * row[1].y() - row[0].y() * rhs[1], row[0].x() * rhs[1] - rhs[0] * row[1].x()) / det;
  m_solution.segment<2>(pin.column) = g;
  for (int k = 0; k < 2; ++k) {
    const BodyId b = step.body[k];
    const ChainUnknown& outer = m_unknowns[step.unknown[2 * k]];
    const Eigen::Vector2d onBody = pin.sign(b) * g;
    const Eigen::Vector2d f = m_load[b.index] - onBody;  // what the outer joint exerts on b
    const double sign = outer.sign(b);
    if (outer.kind == ChainUnknown::Kind::Pin) {
      m_solution.segment<2>(outer.column) = sign * f;
    } else {
      // A block: f = N·n, and with every force at its pin, its reference point, the couple is
      // all of its moment.
      m_solution(outer.column) = sign * f.dot(m_prismaticNormal[outer.slide]);
      m_solution(outer.column + 1) = sign * m_loadMoment[b.index];
    }
  }
  return true;
}

// The steps of m_chain in order, into m_solution. False (nothing decided) if a dyad is within
// kChainMargin of its toggle or a number is not finite: the LU then decides.
bool InverseDynamics::solveLinkByLink(const Pose& pose) {
  bodyRates(pose);
  bodyLoads(pose);
  prismaticNormals(pose);
  for (const ChainStep& step : m_chain) {
    if (step.dyad) {
      if (!solveDyad(pose, step)) return false;
    } else {
      // The crank: F = R from its pin, T = M − (P − O) × R.
      const BodyId b = step.body[0];
      const ChainUnknown& pin = m_unknowns[step.unknown[0]];
      const Eigen::Vector2d& load = m_load[b.index];
      m_solution.segment<2>(pin.column) = pin.sign(b) * load;
      m_solution(m_unknowns[step.unknown[1]].column) =
          m_loadMoment[b.index] - cross(at(pose, pin.point) - m_reference[b.index], load);
    }
    for (const auto& [u, body] : step.passOn) passOn(pose, m_unknowns[u], body);
  }
  return std::isfinite(m_solution.sum());
}

}  // namespace linkwright::kinematics
