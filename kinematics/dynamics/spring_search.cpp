#include "kinematics/dynamics/spring_search.h"

#include "kinematics/dynamics/crank_terms.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

constexpr int kGrid = 9;
constexpr double kSmallestStep = 1e-6;  // of the linkage's size
constexpr double kShortest = 1e-3;      // of the linkage's size: a spring shorter is skipped

// A placement: the link end (u, v) in the link's frame and the frame end (x, y), length unit.
using Placement = std::array<double, 4>;

// Everything a placement's RMS needs, taken once from the turn: per sample, the link's first
// point and its direction, their rates per unit crank rate, and T0.
class PlacementCost {
public:
  PlacementCost(const Mechanism& m, const SweepResult& s, LinkId link, const std::vector<double>& t0, double omega,
                double metres)
      : m_t0(t0), m_metres(metres), m_length(s.size()), m_slope(s.size()), m_angle(s.size()) {
    const Link& l = m.links[link.index];
    for (std::size_t j = 0; j < s.size(); ++j) {
      m_angle[j] = s.inputAngle[j];
      m_base.push_back(s.position[l.first.index][j]);
      m_baseRate.push_back(s.velocity[l.first.index][j] / omega);
      const double theta = s.linkAngle[link.index][j];
      m_along.emplace_back(std::cos(theta), std::sin(theta));
      m_turnRate.push_back(s.linkOmega[link.index][j] / omega);
    }
  }

  /// The fit at `p`, or none where the spring would pass through zero length or not be sized.
  std::optional<SpringFit> fit(const Placement& p, double shortest) {
    const Eigen::Vector2d frame(p[2], p[3]);
    for (std::size_t j = 0; j < m_angle.size(); ++j) {
      const Eigen::Vector2d across(-m_along[j].y(), m_along[j].x());
      const Eigen::Vector2d arm = p[0] * m_along[j] + p[1] * across;
      const Eigen::Vector2d end = m_base[j] + arm;
      const Eigen::Vector2d rate = m_baseRate[j] + m_turnRate[j] * Eigen::Vector2d(-arm.y(), arm.x());
      const Eigen::Vector2d between = end - frame;
      const double length = between.norm();
      if (length < shortest) return std::nullopt;
      m_length[j] = m_metres * length;
      m_slope[j] = m_metres * between.dot(rate) / length;
    }
    const SpringFit f = fitSpring(m_angle, m_t0, m_length, m_slope);
    if (!f.sized || !(f.stiffness > 0.0)) return std::nullopt;
    return f;
  }

private:
  const std::vector<double>& m_t0;
  double m_metres;
  std::vector<double> m_length, m_slope, m_angle, m_turnRate;
  std::vector<Eigen::Vector2d> m_base, m_baseRate, m_along;
};

std::string freeName(const Mechanism& m, const std::string& wanted) {
  std::string name = wanted;
  for (int n = 2; m.findPoint(name); ++n) name = wanted + std::to_string(n);
  return name;
}

}  // namespace

Result<SpringPlacement> searchSpringBalance(const Mechanism& m, const LinkageDynamics& d, const SweepSpec& turn,
                                            const std::string& linkName, const std::string& name) {
  if (auto e = checkCrankTurn(m, turn)) return *e;
  const auto link = m.findLink(linkName);
  if (!link) {
    std::string names;
    for (const Link& l : m.links) names += (names.empty() ? "" : ", ") + l.name;
    return Error{ErrorCode::InvalidValue, "link",
                 "the spring's link must be one of the linkage's (" + names + "); got \"" + linkName + "\""};
  }
  const auto moving = turnForces(m, d, turn, turn.omega, 0.0);
  if (!moving) return moving.error();
  const SweepResult& s = moving->kinematics;

  // The bounds: the link's length, and the box the linkage sweeps widened by a quarter.
  const Link& l = m.links[link->index];
  const double linkLength = (s.position[l.second.index][0] - s.position[l.first.index][0]).norm();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::max()), high = -low;
  for (const auto& column : s.position)
    for (const Eigen::Vector2d& p : column) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  const double size = (high - low).norm();
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(0.25 * size);
  low -= margin;
  high += margin;
  const Placement lower{-0.5 * linkLength, -0.5 * linkLength, low.x(), low.y()};
  const Placement upper{1.5 * linkLength, 0.5 * linkLength, high.x(), high.y()};

  PlacementCost cost(m, s, *link, moving->forces.driveTorque, turn.omega, *metresPerLengthUnit(m.lengthUnit));
  Placement best{};
  double bestRms = std::numeric_limits<double>::infinity();
  const auto tryAt = [&](const Placement& p) {
    const auto f = cost.fit(p, kShortest * size);
    if (f && f->rms < bestRms) {
      bestRms = f->rms;
      best = p;
      return true;
    }
    return false;
  };
  Placement p;
  for (int a = 0; a < kGrid; ++a)
    for (int b = 0; b < kGrid; ++b)
      for (int c = 0; c < kGrid; ++c)
        for (int e = 0; e < kGrid; ++e) {
          const std::array<int, 4> at{a, b, c, e};
          for (std::size_t i = 0; i < 4; ++i) p[i] = lower[i] + (upper[i] - lower[i]) * at[i] / (kGrid - 1);
          tryAt(p);
        }
  if (!std::isfinite(bestRms))
    return Error{ErrorCode::InvalidValue, "spring",
                 "no spring from " + linkName + " to the frame lowers the RMS driving torque"};
  Placement step;
  for (std::size_t i = 0; i < 4; ++i) step[i] = 0.5 * (upper[i] - lower[i]) / (kGrid - 1);
  while (*std::max_element(step.begin(), step.end()) > kSmallestStep * size) {
    bool moved = false;
    for (std::size_t i = 0; i < 4; ++i)
      for (const double sign : {1.0, -1.0}) {
        Placement q = best;
        q[i] = std::clamp(q[i] + sign * step[i], lower[i], upper[i]);
        moved |= tryAt(q);
      }
    if (!moved)
      for (double& h : step) h *= 0.5;
  }

  SpringPlacement r;
  r.mechanism = m;
  r.onLink = {best[0], best[1]};
  r.onFrame = {best[2], best[3]};
  for (std::size_t i = 0; i < 4; ++i) r.atBound |= best[i] == lower[i] || best[i] == upper[i];
  const std::string onLink = freeName(m, name + "_link");
  r.mechanism.points.push_back({onLink, AttachedPoint{*link, best[0], best[1]}});
  const std::string onFrame = freeName(r.mechanism, name + "_frame");
  r.mechanism.points.push_back({onFrame, GroundPoint{r.onFrame}});
  auto balance = balanceBySpring(r.mechanism, d, turn, {linkName, onLink}, {"", onFrame}, name);
  if (!balance) return balance.error();
  r.balance = std::move(balance).value();
  return r;
}

}  // namespace linkwright::kinematics
