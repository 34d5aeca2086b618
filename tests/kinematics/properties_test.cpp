// Properties over hundreds of random four-bars of every Grashof class, with length ratios up
// to 1e4: loop closure, the analytic rates against central differences of positions in time,
// and branch continuity over full sweeps. Deterministic (fixed seed).

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/grashof.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::checkRate;
using linkwright::test::TimeStencil;

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr int kPerClass = 60;

struct Linkage {
  FourBarLengths lengths;
  GrashofClass category = GrashofClass::CrankRocker;
  InputRange range;
  CouplerPointSpec couplerPoint;
};

// Uniform in (0, 1) straight from mt19937's output, which the standard fixes; the standard
// distributions are not, so a library change would otherwise change every linkage drawn.
double unit(std::mt19937& rng) { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; }

double uniform(std::mt19937& rng, double low, double high) { return low + (high - low) * unit(rng); }

double logUniform(std::mt19937& rng, double low, double high) {
  return std::exp(uniform(rng, std::log(low), std::log(high)));
}

double signedLogUniform(std::mt19937& rng, double low, double high) {
  return (unit(rng) < 0.5 ? 1.0 : -1.0) * logUniform(rng, low, high);
}

// kPerClass linkages of each Grashof class (change points have measure zero and are covered by
// extremes_test.cpp), lengths log-uniform over [1, 1e4]. Ranges narrower than 0.05 rad are
// skipped: the samples below keep 10% of a range (and 2e-3 rad of stencil) from each edge.
std::vector<Linkage> randomLinkages() {
  std::mt19937 rng(0x4c696e6bu);
  std::map<GrashofClass, int> count;
  std::vector<Linkage> out;
  for (int draws = 0; out.size() < 4 * kPerClass && draws < 100000; ++draws) {
    Linkage l;
    l.lengths = {logUniform(rng, 1.0, 1e4), logUniform(rng, 1.0, 1e4), logUniform(rng, 1.0, 1e4),
                 logUniform(rng, 1.0, 1e4)};
    l.category = classifyGrashof(l.lengths).category;
    l.range = fourBarInputRange(l.lengths);
    l.couplerPoint = {uniform(rng, -1.0, 2.0) * l.lengths.coupler, uniform(rng, -1.0, 1.0) * l.lengths.coupler};
    if (l.category == GrashofClass::ChangePoint || count[l.category] == kPerClass) continue;
    if (l.range.ranges.empty()) continue;
    if (std::any_of(l.range.ranges.begin(), l.range.ranges.end(),
                    [](const AngleRange& r) { return r.to - r.from < 0.05; }))
      continue;
    ++count[l.category];
    out.push_back(l);
  }
  return out;
}

// A crank angle inside the assemblable range, at least 10% of its width from either edge.
double insideAngle(std::mt19937& rng, const InputRange& range) {
  const AngleRange& r = range.ranges[unit(rng) < 0.5 ? 0 : range.ranges.size() - 1];
  if (range.fullRotation) return uniform(rng, 0.0, 2.0 * kPi);
  return r.from + uniform(rng, 0.1, 0.9) * (r.to - r.from);
}

double total(const FourBarLengths& l) { return l.frame + l.crank + l.coupler + l.rocker; }

}  // namespace

TEST_CASE("The random linkages cover every Grashof class and ratios up to 1e4", "[properties]") {
  const std::vector<Linkage> linkages = randomLinkages();
  REQUIRE(linkages.size() == 4 * kPerClass);
  std::map<GrashofClass, int> count;
  double widest = 1.0;
  for (const Linkage& l : linkages) {
    ++count[l.category];
    const auto [low, high] = std::minmax({l.lengths.frame, l.lengths.crank, l.lengths.coupler, l.lengths.rocker});
    widest = std::max(widest, high / low);
  }
  CHECK(count[GrashofClass::CrankRocker] == kPerClass);
  CHECK(count[GrashofClass::DoubleCrank] == kPerClass);
  CHECK(count[GrashofClass::DoubleRocker] == kPerClass);
  CHECK(count[GrashofClass::TripleRocker] == kPerClass);
  CHECK(widest > 1e3);
}

TEST_CASE("Loop closure and analytic rates against time differences of positions", "[properties]") {
  std::mt19937 rng(20240611u);
  int poses = 0;
  for (const Linkage& l : randomLinkages()) {
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      const auto m = makeFourBar(l.lengths, branch, "mm", l.couplerPoint);
      REQUIRE(m.ok());
      for (int sample = 0; sample < 3; ++sample) {
        const DriverState state{insideAngle(rng, l.range), signedLogUniform(rng, 0.1, 100.0),
                                signedLogUniform(rng, 0.1, 1000.0)};
        CAPTURE(l.lengths.frame, l.lengths.crank, l.lengths.coupler, l.lengths.rocker, toString(l.category),
                branch == Branch::Open, state.position, state.velocity, state.acceleration);
        const auto pose = solvePose(*m, state);
        INFO((pose.ok() ? std::string() : pose.error().message));
        REQUIRE(pose.ok());
        const Pose& p = *pose;
        ++poses;

        // Loop closure: each length to 1e-10 of the linkage's size (ε·size is 2e-16).
        const double size = total(l.lengths);
        const auto& x = p.position;
        CHECK((x[fourbar::kB.index] - x[fourbar::kO2.index]).norm() ==
              linkwright::test::within(l.lengths.crank, 1e-10 * size));
        CHECK((x[fourbar::kC.index] - x[fourbar::kB.index]).norm() ==
              linkwright::test::within(l.lengths.coupler, 1e-10 * size));
        CHECK((x[fourbar::kC.index] - x[fourbar::kO4.index]).norm() ==
              linkwright::test::within(l.lengths.rocker, 1e-10 * size));
        const double side = std::sin(p.linkAngle[fourbar::kRocker.index] - p.linkAngle[fourbar::kCoupler.index]);
        CHECK((side > 0.0) == (branch == Branch::Open));

        // Step: the crank turns δ = 1e-3 rad per h (δ² ≈ 1e-6 truncation, δ large enough that
        // round-off stays ~ε/δ² ≈ 2e-10 relative for second differences).
        const double h = 1e-3 / (std::abs(state.velocity) + std::sqrt(std::abs(state.acceleration)));
        const TimeStencil stencil(*m, state, h);
        // Position round-off: B = O2 + a·(cos, sin) carries a few ulps of a; C and P a few dozen
        // roundings of coordinates up to the linkage's size, amplified by 1/sin μ in the dyad
        // (the rows of its 2×2 system are nearly parallel). A link angle's round-off is its
        // ends' round-off over its length.
        const double sine = std::max(std::sin(p.transmissionAngle[fourbar::kC.index]), 1e-3);
        const double noiseB = 8.0 * kEpsilon * l.lengths.crank;
        const double noise =
            64.0 * kEpsilon * (size + std::abs(l.couplerPoint.along) + std::abs(l.couplerPoint.across)) / sine;
        const double angleNoise[] = {noiseB / l.lengths.crank, (noiseB + noise) / l.lengths.coupler,
                                     noise / l.lengths.rocker};
        for (const LinkId link : {fourbar::kCrank, fourbar::kCoupler, fourbar::kRocker}) {
          const auto d = stencil.link(link, angleNoise[link.index]);
          checkRate(p.linkOmega[link.index], d[0], "omega of link " + std::to_string(link.index));
          checkRate(p.linkAlpha[link.index], d[1], "alpha of link " + std::to_string(link.index));
        }
        for (const PointId point : {fourbar::kC, fourbar::kCouplerPoint}) {
          for (int axis = 0; axis < 2; ++axis) {
            const auto d = stencil.point(point, axis, noise);
            const std::string what = "point " + std::to_string(point.index) + " axis " + std::to_string(axis);
            checkRate(p.velocity[point.index][axis], d[0], "velocity of " + what);
            checkRate(p.acceleration[point.index][axis], d[1], "acceleration of " + what);
          }
        }
      }
    }
  }
  CHECK(poses == 4 * kPerClass * 2 * 3);
}

TEST_CASE("A full sweep keeps its branch and moves continuously", "[properties]") {
  // The thesis crank-rocker, a double-crank, and random ones of both kinds.
  std::vector<FourBarLengths> cases{linkwright::test::kThesis, {25.0, 60.0, 45.0, 70.0}};
  int crankRockers = 0, doubleCranks = 0;
  for (const Linkage& l : randomLinkages()) {
    if (l.category == GrashofClass::CrankRocker && l.range.fullRotation && crankRockers++ < 10)
      cases.push_back(l.lengths);
    if (l.category == GrashofClass::DoubleCrank && doubleCranks++ < 10) cases.push_back(l.lengths);
  }
  REQUIRE(cases.size() == 22);
  for (const FourBarLengths& l : cases) {
    const bool doubleCrank = classifyGrashof(l).category == GrashofClass::DoubleCrank;
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      CAPTURE(l.frame, l.crank, l.coupler, l.rocker, branch == Branch::Open);
      const auto m = makeFourBar(l, branch);
      REQUIRE(m.ok());
      const std::size_t samples = 1441;
      const auto s = sweep(*m, {0.0, 2.0 * kPi, samples, 1.0, 0.0});
      REQUIRE(s.ok());
      REQUIRE(s->singularAngles.empty());
      REQUIRE(s->notAssembled.empty());
      const double step = 2.0 * kPi / static_cast<double>(samples - 1);
      for (std::size_t k = 0; k < 3; ++k) {
        CAPTURE(k);
        const auto& angle = s->linkAngle[k];
        const auto& omega = s->linkOmega[k];
        // With ω2 = 1, ω is dθ/dθ2: a step cannot move a link further than the fastest rate
        // seen times the step, with a factor 2 for a peak between samples. A branch flip
        // jumps by the angle between the two candidates instead.
        double fastest = 0.0;
        for (const double w : omega) fastest = std::max(fastest, std::abs(w));
        for (std::size_t j = 1; j < samples; ++j)
          if (std::abs(angle[j] - angle[j - 1]) > 2.0 * fastest * step + 1e-12)
            FAIL_CHECK("jump of " << radToDeg(angle[j] - angle[j - 1]) << "° at sample " << j);
      }
      // The Pose-level branch stays the one chosen: sign of sin(θ4 − θ3) at every sample.
      const double sign = branch == Branch::Open ? 1.0 : -1.0;
      for (std::size_t j = 0; j < samples; ++j) {
        const double side =
            std::sin(s->linkAngle[fourbar::kRocker.index][j] - s->linkAngle[fourbar::kCoupler.index][j]);
        if (side * sign <= 0.0) FAIL_CHECK("branch changed at sample " << j);
      }
      // Unwrapped over one turn: the crank gains 2π. In a crank-rocker the coupler and rocker
      // return; in a double-crank (frame shortest) every moving link turns fully relative to the
      // frame, so they gain 2π too, crossing ±180° on the way.
      const auto net = [&](LinkId k) { return s->linkAngle[k.index].back() - s->linkAngle[k.index].front(); };
      CHECK(net(fourbar::kCrank) == linkwright::test::within(2.0 * kPi, 1e-9));
      CHECK(net(fourbar::kCoupler) == linkwright::test::within(doubleCrank ? 2.0 * kPi : 0.0, 1e-9));
      CHECK(net(fourbar::kRocker) == linkwright::test::within(doubleCrank ? 2.0 * kPi : 0.0, 1e-9));
    }
  }
}
