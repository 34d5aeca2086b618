#include "tests/kinematics/soak/soak_checks.h"

#include "kinematics/solve/pose_solver.h"
#include "tests/support/approx.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace linkwright::test {
namespace k = kinematics;

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

std::string at(const k::SweepResult& s, std::size_t j) {
  std::ostringstream out;
  out.precision(17);
  out << "sample " << j << " (crank " << s.inputAngle[j] << " rad)";
  return out.str();
}

// The largest coordinate of any point at any assembled sample: the linkage's size.
double sizeOf(const k::SweepResult& s) {
  double size = 0.0;
  for (const auto& column : s.position)
    for (std::size_t j = 0; j < column.size(); ++j)
      if (s.assembled(j) && column[j].allFinite()) size = std::max(size, column[j].cwiseAbs().maxCoeff());
  return size;
}

void checkFinite(const k::Mechanism& m, const k::SweepResult& s, std::size_t j, SweepCheck& c) {
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (!s.position[i][j].allFinite())
      c.findings.push_back("position of " + m.points[i].name + " not finite at " + at(s, j));
    if (s.ok(j) && !(s.velocity[i][j].allFinite() && s.acceleration[i][j].allFinite()))
      c.findings.push_back("velocity or acceleration of " + m.points[i].name + " not finite at " + at(s, j));
  }
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    if (!std::isfinite(s.linkAngle[l][j]))
      c.findings.push_back("angle of " + m.links[l].name + " not finite at " + at(s, j));
    if (s.ok(j) && !(std::isfinite(s.linkOmega[l][j]) && std::isfinite(s.linkAlpha[l][j])))
      c.findings.push_back("ω or α of " + m.links[l].name + " not finite at " + at(s, j));
  }
}

// Every link keeps the length it has at the first assembled sample; every distance constraint
// holds its length.
void checkClosure(const k::Mechanism& m, const k::SweepResult& s, double size, std::size_t first, std::size_t j,
                  SweepCheck& c) {
  const auto distance = [&](k::PointId a, k::PointId b, std::size_t sample) {
    return (s.position[a.index][sample] - s.position[b.index][sample]).norm();
  };
  const auto misfit = [&](double error, const std::string& what) {
    const double relative = error / size;
    c.worstClosure = std::max(c.worstClosure, relative);
    if (!(relative <= kClosureTolerance))
      c.findings.push_back(what + " misfit " + std::to_string(relative) + " of the size at " + at(s, j));
  };
  for (const k::Link& link : m.links)
    misfit(std::abs(distance(link.first, link.second, j) - distance(link.first, link.second, first)),
           "link " + link.name);
  for (const k::DistanceConstraint& dc : m.constraints)
    misfit(std::abs(distance(dc.first, dc.second, j) - dc.length),
           "constraint " + m.points[dc.first.index].name + "–" + m.points[dc.second.index].name);
}

// Between consecutive samples where the rates exist, each point moves about as far as its
// rates say: p' = v/ω and p'' = (a − p'α)/ω² per radian of crank. A point that switched
// assembly branch jumps by far more. Strongly curved steps (p''Δθ > p', near a toggle) are
// left out: there the Taylor bound says little.
void checkContinuity(const k::Mechanism& m, const k::SweepSpec& spec, const k::SweepResult& s, double size,
                     std::size_t j, SweepCheck& c) {
  const double step = std::abs(s.inputAngle[j + 1] - s.inputAngle[j]);
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    double slope = 0.0, curvature = 0.0;
    for (const std::size_t n : {j, j + 1}) {
      const Eigen::Vector2d d1 = s.velocity[i][n] / spec.omega;
      const Eigen::Vector2d d2 = (s.acceleration[i][n] - d1 * spec.alpha) / (spec.omega * spec.omega);
      slope = std::max(slope, d1.norm());
      curvature = std::max(curvature, d2.norm());
    }
    if (curvature * step > slope) continue;
    const double moved = (s.position[i][j + 1] - s.position[i][j]).norm();
    const double bound = 3.0 * (slope * step + 0.5 * curvature * step * step) + kClosureTolerance * size;
    if (!(moved <= bound))
      c.findings.push_back(m.points[i].name + " jumps " + std::to_string(moved) + " (rates allow " +
                           std::to_string(bound) + ") between " + at(s, j) + " and the next: a branch switch");
  }
}

// The pose at crank angle θ0 + ωt + αt²/2 for t = −2h..2h, positions only, or nothing if one
// does not assemble or the middle one is not the sweep's (the stencil solves each pose from
// the mechanism's branch flags and guesses, which a sweep that tracked through a change point
// or a Newton warm start has left).
std::optional<std::array<k::Pose, 5>> stencil(const k::Mechanism& m, const k::SweepSpec& spec, const k::SweepResult& s,
                                              std::size_t j, double h, double size) {
  std::array<k::Pose, 5> poses;
  for (int n = -2; n <= 2; ++n) {
    const double t = n * h;
    const auto pose =
        k::solvePose(m, {s.inputAngle[j] + spec.omega * t + 0.5 * spec.alpha * t * t, 0.0, 0.0}, {false, false});
    if (!pose) return std::nullopt;
    poses[static_cast<std::size_t>(n + 2)] = *pose;
  }
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if ((poses[2].position[i] - s.position[i][j]).norm() > kClosureTolerance * size) return std::nullopt;
  return poses;
}

void compare(double exact, const Estimate& e, const std::string& what, const k::SweepResult& s, std::size_t j,
             SweepCheck& c) {
  const double error = std::abs(exact - e.value);
  c.worstRateRatio = std::max(c.worstRateRatio, e.tolerance > 0.0 ? error / e.tolerance : (error > 0.0 ? 1e300 : 0.0));
  if (!(error <= e.tolerance)) {
    std::ostringstream out;
    out.precision(17);
    out << what << " at " << at(s, j) << ": exact " << exact << ", difference " << e.value << " ± " << e.tolerance;
    c.findings.push_back(out.str());
  }
}

// True if a driven point's polyline path turns a corner within `reach` of input q: there its
// velocity jumps, and differences across the corner say nothing about the rates either side.
bool cornerWithin(const k::Mechanism& m, double q, double reach) {
  for (const k::Point& p : m.points) {
    const auto* driven = std::get_if<k::PathPoint>(&p.definition);
    const auto* line = driven != nullptr ? std::get_if<k::PolylinePath>(&driven->path) : nullptr;
    if (line == nullptr) continue;
    double corner = 0.0;
    for (std::size_t v = 0; v + 2 < line->vertices.size(); ++v) {
      corner += (line->vertices[v + 1] - line->vertices[v]).norm();
      if (std::abs(corner - q) <= reach) return true;
    }
  }
  return false;
}

void checkRates(const k::Mechanism& m, const k::SweepSpec& spec, const k::SweepResult& s, double size, std::size_t j,
                double inputScale, SweepCheck& c) {
  // Near a toggle the rates are steep and the differences meaningless: keep 1e-3 of the size.
  const auto pose = k::solvePose(m, {s.inputAngle[j], spec.omega, spec.alpha});
  double gap = size;
  if (pose)
    for (std::size_t i = 0; i < m.points.size(); ++i)
      if (pose->branchSign[i] != 0) gap = std::min(gap, pose->assemblyGap[i]);
  // The crank turns 1e-3 rad over the stencil's step h (a linear input moves 1e-3 of its
  // scale), less near a toggle: there the n-th derivative grows like (size/gap)^n, and the
  // Richardson estimate of the truncation error only holds while a step of the crank moves
  // the dyad by much less than its gap.
  const double turn = 1e-3 * std::min(1.0, 10.0 * gap / size);
  const double h = turn * inputScale / (std::abs(spec.omega) + std::sqrt(std::abs(spec.alpha) * inputScale));
  const bool smooth = !cornerWithin(m, s.inputAngle[j], 2.0 * h * (std::abs(spec.omega) + h * std::abs(spec.alpha)));
  const auto poses = pose && gap > 1e-3 * size && smooth ? stencil(m, spec, s, j, h, size) : std::nullopt;
  if (!poses) {
    ++c.ratesSkipped;
    return;
  }
  ++c.ratesCompared;
  // Position round-off, amplified by how close the dyads are to a toggle (size/gap), and
  // Newton's closure tolerance for free points.
  const double noise = std::max(64.0 * kEpsilon * size * size / gap, 1e-12 * size);
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      std::array<double, 5> q{};
      for (std::size_t n = 0; n < 5; ++n) q[n] = (*poses)[n].position[i][axis];
      const auto d = differentiate(q, h, noise);
      const std::string what = m.points[i].name + (axis == 0 ? ".x" : ".y");
      compare(s.velocity[i][j][axis], d[0], "velocity of " + what, s, j, c);
      compare(s.acceleration[i][j][axis], d[1], "acceleration of " + what, s, j, c);
    }
  }
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    const k::Link& link = m.links[l];
    const double length = (s.position[link.second.index][j] - s.position[link.first.index][j]).norm();
    std::array<double, 5> q{};
    const double centre = (*poses)[2].linkAngle[l];
    for (std::size_t n = 0; n < 5; ++n) q[n] = centre + angleDifference((*poses)[n].linkAngle[l], centre);
    const auto d = differentiate(q, h, 2.0 * noise / length);
    compare(s.linkOmega[l][j], d[0], "ω of " + link.name, s, j, c);
    compare(s.linkAlpha[l][j], d[1], "α of " + link.name, s, j, c);
  }
}

}  // namespace

SweepCheck checkSweep(const k::Mechanism& m, const k::SweepSpec& spec, const k::SweepResult& s, std::size_t rateSamples,
                      double inputScale) {
  SweepCheck c;
  const double size = std::max(sizeOf(s), std::numeric_limits<double>::min());
  std::optional<std::size_t> first;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.assembled(j)) continue;
    ++c.assembled;
    const std::size_t before = c.findings.size();
    checkFinite(m, s, j, c);
    if (c.findings.size() > before) continue;
    if (!first) first = j;
    checkClosure(m, s, size, *first, j, c);
    if (j + 1 < s.size() && s.ok(j) && s.ok(j + 1) && spec.omega != 0.0 && !s.lockedAfter(j))
      checkContinuity(m, spec, s, size, j, c);
  }
  // Rates at up to rateSamples samples spread evenly over the ok ones.
  std::vector<std::size_t> ok;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.ok(j)) ok.push_back(j);
  const std::size_t count = std::min(rateSamples, ok.size());
  for (std::size_t n = 0; n < count && c.findings.empty(); ++n)
    checkRates(m, spec, s, size, ok[n * ok.size() / count], inputScale, c);
  return c;
}

}  // namespace linkwright::test
