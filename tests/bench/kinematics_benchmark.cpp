// Speed of the kinematics core (issue 5): the cost per sample of a sweep at each level of a
// request (positions; + ω and v; + α and a; + transmission angles; + a coupler point's path;
// one link only; + forces) for the four-bar, the slider-crank, the shaper and two six-bars,
// sweeps of 36 to 1,000,000 samples, one pose solved into a prepared Pose, and hand-written
// closed-form four-bar loops as the baseline the core is judged against. Names read
// Mechanism/Level/Samples; one item is one sample. docs/benchmarks.md says how to run it and
// what was measured.
//
// Allocations are counted by replacing the global operator new: each benchmark reports
// `allocs_per_sample` and `allocs_per_call` over its timed loop.

#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/constraint_form.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

using namespace linkwright::kinematics;

// The allocation counter has to be global: operator new has no other place to report to. It
// is the benchmark's instrument, not program state (the style's "no mutable statics" is about
// the product).
namespace {
std::atomic<std::uint64_t> gAllocations{0};

void* countedAllocation(std::size_t size) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* countedAlignedAllocation(std::size_t size, std::align_val_t alignment) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  const auto align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + align - 1) / align * align;  // aligned_alloc's precondition
  if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return countedAllocation(size); }
void* operator new[](std::size_t size) { return countedAllocation(size); }
void* operator new(std::size_t size, std::align_val_t a) { return countedAlignedAllocation(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return countedAlignedAllocation(size, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace {

const std::vector<std::int64_t> kSizes{36, 360, 3600, 36000, 1000000};

// Minor page faults so far: a fresh multi-megabyte allocation is paid for in page faults (the
// kernel zeroes each new page) when it is first written, not when malloc returns.
std::int64_t pageFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Counts allocations and page faults over the timed loop only.
class Instruments {
public:
  Instruments() : m_allocations(gAllocations.load()), m_faults(pageFaults()) {}

  // One item is one sample.
  void report(benchmark::State& state, std::int64_t samplesPerCall) const {
    const auto calls = static_cast<double>(state.iterations());
    const double samples = calls * static_cast<double>(samplesPerCall);
    const auto allocations = static_cast<double>(gAllocations.load() - m_allocations);
    state.SetItemsProcessed(state.iterations() * samplesPerCall);
    state.counters["allocs_per_call"] = allocations / calls;
    state.counters["allocs_per_sample"] = allocations / samples;
    state.counters["faults_per_sample"] = static_cast<double>(pageFaults() - m_faults) / samples;
  }

private:
  std::uint64_t m_allocations;
  std::int64_t m_faults;
};

// --- The linkages ------------------------------------------------------------------------

struct Subject {
  std::string name;    // "FourBar", "SliderCrank", "Shaper"
  Mechanism plain;     // as built
  Mechanism withPath;  // plus one point fixed on the coupler (or rod, or link)
  double omega = 0.0;  // rad/s, the example's crank speed
};

// A built-in four-bar example by its dimensions and crank speed.
struct FourBarSubject {
  FourBarLengths lengths;
  Branch branch = Branch::Open;
  double omega = 0.0;  // rad/s
};

FourBarSubject fourBarExample(const std::string& name) {
  const Example example = findExample(name).value();
  const FourBarStructure s = asFourBar(example.mechanism).value();
  return {s.lengths, s.branch, example.omega};
}

const FourBarSubject& thesis() {
  static const FourBarSubject example = fourBarExample("thesis-crank-rocker");
  return example;
}

// The README's coupler point for the thesis linkage (--coupler-point 35,20).
constexpr CouplerPointSpec kThesisCouplerPoint{35.0, 20.0};

Mechanism withPointOn(Mechanism m, LinkId link, double along, double across) {
  m.points.push_back({"P", AttachedPoint{link, along, across}});
  return m;
}

std::vector<Subject> subjects() {
  const FourBarSubject& t = thesis();
  const Mechanism sliderCrank = makeSliderCrank(kLs3Engine).value();
  const Mechanism shaperMechanism = makeShaper(kSeedShaper).value();
  return {
      {"FourBar", makeFourBar(t.lengths, t.branch).value(),
       makeFourBar(t.lengths, t.branch, "mm", kThesisCouplerPoint).value(), t.omega},
      {"SliderCrank", sliderCrank, withPointOn(sliderCrank, slidercrank::kRod, 0.3 * kLs3Engine.rod, 0.0),
       2.0 * kPi * 110.0},
      {"Shaper", shaperMechanism, withPointOn(shaperMechanism, shaper::kLink, 0.5 * kSeedShaper.link, 20.0),
       2.0 * kPi * 3.0},
      {"SixBar", makeSixBar(kWattIISixBar).value(), makeSixBar(kWattIISixBar).value(), 2.0 * kPi},  // P is its point
      {"SixBarNewton", makeStephensonIINewton().value(), makeStephensonIINewton().value(), 2.0 * kPi},
  };
}

// --- Sweeps through the core -------------------------------------------------------------

// What a scene asks for: every link and point (Positions, Velocities, Full: the issue's "all
// positions, ω and α of every link"), plus every dyad's transmission angle (Transmission), plus
// a coupler point's path (Paths), or one plot's worth: angle, ω and α of the output link alone
// (OutputLink: the last link), or of the base four-bar's rocker on a six-bar (FourBarRocker:
// the added dyad is not solved at all).
enum class Only { Everything, LastLink, FourBarRocker };

struct Level {
  const char* name;
  bool velocities;
  bool accelerations;
  bool transmission;
  bool path;
  Only only;
};

constexpr Level kLevels[] = {
    {"Positions", false, false, false, false, Only::Everything},
    {"Velocities", true, false, false, false, Only::Everything},
    {"Full", true, true, false, false, Only::Everything},
    {"Transmission", true, true, true, false, Only::Everything},
    {"Paths", true, true, true, true, Only::Everything},
    {"OutputLink", true, true, false, false, Only::LastLink},
    {"FourBarRocker", true, true, false, false, Only::FourBarRocker},
};

SolveRequest requestFor(const Level& level, const Mechanism& m) {
  SolveRequest request{level.velocities, level.accelerations};
  request.transmissionAngles = level.transmission;
  if (level.only == Only::Everything) return request;
  const LinkId link = level.only == Only::LastLink ? LinkId{m.links.size() - 1} : fourbar::kRocker;
  request.only = Selection{std::vector<PointId>{}, std::vector<LinkId>{link}};
  return request;
}

// Each iteration sweeps into the same SweepResult (sweepInto), as the GUI re-sweeps during a
// drag and as the hand-written loop below reuses its columns: the fixed per-call cost left is
// the tracker's few scratch poses. sweep(), which returns a fresh result and so pays for new
// pages on every call, is measured as <mechanism>/Fresh.
void sweepBenchmark(benchmark::State& state, const Mechanism& mechanism, double omega, SolveRequest request) {
  const auto samples = static_cast<std::size_t>(state.range(0));
  const SweepSpec spec{0.0, 2.0 * kPi, samples, omega, 0.5};
  {
    const auto check = sweep(mechanism, spec, request);
    if (!check.ok() || !check->notAssembled.empty() || !check->singularAngles.empty()) {
      state.SkipWithError("the benchmark's sweep does not assemble everywhere");
      return;
    }
  }
  SweepResult result;
  const Instruments instruments;
  for (auto _ : state) {
    auto error = sweepInto(mechanism, spec, request, result);  // not const: DoNotOptimize(const&) is deprecated
    benchmark::DoNotOptimize(error);
    benchmark::DoNotOptimize(result.linkAlpha.data());
    benchmark::ClobberMemory();
  }
  instruments.report(state, state.range(0));
}

void freshSweepBenchmark(benchmark::State& state, const Mechanism& mechanism, double omega) {
  const SweepSpec spec{0.0, 2.0 * kPi, static_cast<std::size_t>(state.range(0)), omega, 0.5};
  const Instruments instruments;
  for (auto _ : state) {
    auto result = sweep(mechanism, spec, SolveRequest{});
    benchmark::DoNotOptimize(result);
    benchmark::ClobberMemory();
  }
  instruments.report(state, state.range(0));
}

// The "+ forces" level: the Full sweep and then inverse dynamics at every sample
// (force_sweep.h), for seed 004's four-bar with its masses (funsho-fourbar).
void forcesBenchmark(benchmark::State& state) {
  const Example e = findExample("funsho-fourbar").value();
  const Mechanism& m = e.mechanism;
  const SweepSpec spec{0.0, 2.0 * kPi, static_cast<std::size_t>(state.range(0)), e.omega, 0.5};
  SweepResult kinematics;
  const Instruments instruments;
  for (auto _ : state) {
    auto error = sweepInto(m, spec, SolveRequest{}, kinematics);
    auto forces = sweepForces(m, e.dynamics, kinematics);
    benchmark::DoNotOptimize(error);
    benchmark::DoNotOptimize(forces);
    benchmark::ClobberMemory();
  }
  instruments.report(state, state.range(0));
}

// --- One pose ------------------------------------------------------------------------------

void poseBenchmark(benchmark::State& state, const Mechanism& mechanism, double omega) {
  Pose pose;
  preparePose(mechanism, pose);
  const SolveRequest full{true, true};
  const double step = 2.0 * kPi / 3600.0;
  double angle = 0.0;
  const Instruments instruments;
  for (auto _ : state) {
    PoseReport r = solvePoseInto(mechanism, {angle, omega, 0.5}, full, pose);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(pose.linkAlpha.data());
    benchmark::ClobberMemory();
    angle = angle + step < 2.0 * kPi ? angle + step : 0.0;
  }
  instruments.report(state, 1);
}

// --- The hand-written baseline -------------------------------------------------------------

// What a careful hand-written closed-form four-bar loop costs: the crank tip, the dyad joint C
// by the same Heron form as rrr_dyad.h, link angles by atan2, and rates from the differentiated
// loop a·e^{iθ2} + b·e^{iθ3} = d + c·e^{iθ4} (Norton's formulas, written with the links' unit
// vectors instead of sines of angle differences). No branch tracking, no checks, open branch.
struct HandWrittenColumns {
  std::vector<double> theta3, theta4, omega3, omega4, alpha3, alpha4;
  // The rest of what FourBar/Full stores, filled only by the "everything" variant: the crank's
  // angle and rates, and the moving joints' positions, velocities and accelerations.
  std::vector<double> theta2, omega2, alpha2;
  std::vector<Eigen::Vector2d> b, vB, aB, c, vC, aC;
  HandWrittenColumns(std::size_t n, bool everything)
      : theta3(n), theta4(n), omega3(n), omega4(n), alpha3(n), alpha4(n) {
    if (!everything) return;
    for (auto* column : {&theta2, &omega2, &alpha2}) column->resize(n);
    for (auto* column : {&b, &vB, &aB, &c, &vC, &aC}) column->resize(n);
  }
};

// Everything: also store what FourBar/Full stores beyond the six output columns.
template <bool Everything>
void handWrittenFourBar(const FourBarLengths& l, double from, double to, double omega2, double alpha2,
                        HandWrittenColumns& out) {
  const std::size_t n = out.theta3.size();
  const double a = l.crank, b = l.coupler, c = l.rocker, d = l.frame;
  const double step = n > 1 ? (to - from) / static_cast<double>(n - 1) : 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double theta2 = from + static_cast<double>(j) * step;
    const double c2 = std::cos(theta2), s2 = std::sin(theta2);
    const double bx = a * c2, by = a * s2;
    // Dyad B–C–O4: C = B + along·u + h·n, u = (O4 − B)/L.
    const double ux = d - bx, uy = -by;
    const double len = std::sqrt(ux * ux + uy * uy);
    const double along = (b * b - c * c + len * len) / (2.0 * len);
    const double h = std::sqrt(std::max(b * b - along * along, 0.0));
    const double cx = bx + (along * ux - h * uy) / len;
    const double cy = by + (along * uy + h * ux) / len;
    // Unit vectors of coupler (B→C) and rocker (O4→C).
    const double e3x = (cx - bx) / b, e3y = (cy - by) / b;
    const double e4x = (cx - d) / c, e4y = cy / c;
    out.theta3[j] = std::atan2(e3y, e3x);
    out.theta4[j] = std::atan2(e4y, e4x);
    // Velocity: a·ω2·i·e2 + b·ω3·i·e3 = c·ω4·i·e4; cross with e4, then with e3.
    const double cross34 = e3x * e4y - e3y * e4x;  // sin(θ4 − θ3)
    const double cross24 = c2 * e4y - s2 * e4x;    // sin(θ4 − θ2)
    const double cross23 = c2 * e3y - s2 * e3x;    // sin(θ3 − θ2)
    const double w3 = -a * omega2 * cross24 / (b * cross34);
    const double w4 = -a * omega2 * cross23 / (c * cross34);
    out.omega3[j] = w3;
    out.omega4[j] = w4;
    // Acceleration: a(α2·i − ω2²)e2 + b(α3·i − ω3²)e3 = c(α4·i − ω4²)e4. The known part
    // k = a(α2·i − ω2²)e2 − b·ω3²·e3 + c·ω4²·e4 leaves b·α3·i·e3 − c·α4·i·e4 = −k.
    const double kx = a * (-alpha2 * s2 - omega2 * omega2 * c2) - b * w3 * w3 * e3x + c * w4 * w4 * e4x;
    const double ky = a * (alpha2 * c2 - omega2 * omega2 * s2) - b * w3 * w3 * e3y + c * w4 * w4 * e4y;
    // With i·e = (−ey, ex): (i·e3)·e4 = cross34, (i·e4)·e3 = −cross34, (i·e)·e = 0, so
    // dotting with e4 gives b·α3·cross34 = −k·e4, and with e3, c·α4·cross34 = −k·e3.
    const double a3 = -(kx * e4x + ky * e4y) / (b * cross34);
    const double a4 = -(kx * e3x + ky * e3y) / (c * cross34);
    out.alpha3[j] = a3;
    out.alpha4[j] = a4;
    if constexpr (Everything) {
      out.theta2[j] = theta2;
      out.omega2[j] = omega2;
      out.alpha2[j] = alpha2;
      // B = a·e2 and C = O4 + c·e4: v = ω·i·(r), a = α·i·(r) − ω²·r about the fixed pivots.
      out.b[j] = {bx, by};
      out.vB[j] = {-omega2 * by, omega2 * bx};
      out.aB[j] = {-alpha2 * by - omega2 * omega2 * bx, alpha2 * bx - omega2 * omega2 * by};
      const double rx = cx - d, ry = cy;
      out.c[j] = {cx, cy};
      out.vC[j] = {-w4 * ry, w4 * rx};
      out.aC[j] = {-a4 * ry - w4 * w4 * rx, a4 * rx - w4 * w4 * ry};
    }
  }
}

template <bool Everything>
void handWrittenBenchmark(benchmark::State& state) {
  const auto samples = static_cast<std::size_t>(state.range(0));
  HandWrittenColumns columns(samples, Everything);
  const FourBarSubject& t = thesis();
  const Instruments instruments;
  for (auto _ : state) {
    handWrittenFourBar<Everything>(t.lengths, 0.0, 2.0 * kPi, t.omega, 0.5, columns);
    benchmark::DoNotOptimize(columns.alpha4.data());
    benchmark::DoNotOptimize(columns.aC.data());
    benchmark::ClobberMemory();
  }
  instruments.report(state, state.range(0));
}

// The baselines must compute what the core computes, or the comparison means nothing: every
// column the "everything" loop fills against the core's, relative to the value's size.
bool handWrittenMatchesCore() {
  const FourBarSubject& t = thesis();
  const std::size_t n = 361;
  HandWrittenColumns hand(n, true);
  handWrittenFourBar<true>(t.lengths, 0.0, 2.0 * kPi, t.omega, 0.5, hand);
  const auto core = sweep(makeFourBar(t.lengths, t.branch).value(), {0.0, 2.0 * kPi, n, t.omega, 0.5});
  if (!core.ok()) return false;
  double worst = 0.0;
  auto angle = [&](double h, double c) { worst = std::max(worst, std::abs(std::remainder(h - c, 2.0 * kPi))); };
  auto value = [&](double h, double c) { worst = std::max(worst, std::abs(h - c) / std::max(1.0, std::abs(c))); };
  auto point = [&](const Eigen::Vector2d& h, const Eigen::Vector2d& c) {
    value(h.x(), c.x());
    value(h.y(), c.y());
  };
  const auto crank = fourbar::kCrank.index, coupler = fourbar::kCoupler.index, rocker = fourbar::kRocker.index;
  const auto b = fourbar::kB.index, c = fourbar::kC.index;
  for (std::size_t j = 0; j < n; ++j) {
    angle(hand.theta2[j], core->linkAngle[crank][j]);
    angle(hand.theta3[j], core->linkAngle[coupler][j]);
    angle(hand.theta4[j], core->linkAngle[rocker][j]);
    value(hand.omega2[j], core->linkOmega[crank][j]);
    value(hand.omega3[j], core->linkOmega[coupler][j]);
    value(hand.omega4[j], core->linkOmega[rocker][j]);
    value(hand.alpha2[j], core->linkAlpha[crank][j]);
    value(hand.alpha3[j], core->linkAlpha[coupler][j]);
    value(hand.alpha4[j], core->linkAlpha[rocker][j]);
    point(hand.b[j], core->position[b][j]);
    point(hand.vB[j], core->velocity[b][j]);
    point(hand.aB[j], core->acceleration[b][j]);
    point(hand.c[j], core->position[c][j]);
    point(hand.vC[j], core->velocity[c][j]);
    point(hand.aC[j], core->acceleration[c][j]);
  }
  if (worst > 1e-9) std::fprintf(stderr, "hand-written four-bar differs from the core by %g\n", worst);
  return worst <= 1e-9;
}

void registerAll() {
  for (const Subject& s : subjects()) {
    for (const Level& level : kLevels) {
      if (level.path && s.withPath.points.size() == s.plain.points.size()) continue;
      if (level.only == Only::FourBarRocker && s.name != "SixBar") continue;
      const Mechanism& m = level.path ? s.withPath : s.plain;
      const std::string name = s.name + "/" + level.name;
      auto* b = benchmark::RegisterBenchmark(name.c_str(), sweepBenchmark, m, s.omega, requestFor(level, m));
      for (const std::int64_t n : kSizes) b->Arg(n);
      b->Unit(benchmark::kNanosecond);
    }
    auto* fresh = benchmark::RegisterBenchmark((s.name + "/Fresh").c_str(), freshSweepBenchmark, s.plain, s.omega);
    for (const std::int64_t n : kSizes) fresh->Arg(n);
    fresh->Unit(benchmark::kNanosecond);
  }
  // Newton on the same four-bar (its joint C as a free point), against FourBar/Full above, and
  // its cost against its tolerance at 3600 samples.
  const Mechanism closed = makeFourBar(thesis().lengths, thesis().branch).value();
  const Mechanism newton = withNewtonPoints(closed, solvePose(closed, {0.0, 1.0, 0.0}).value().position);
  auto* full =
      benchmark::RegisterBenchmark("FourBar/NewtonFull", sweepBenchmark, newton, thesis().omega, SolveRequest{});
  for (const std::int64_t n : kSizes) full->Arg(n);
  full->Unit(benchmark::kNanosecond);
  for (const double tolerance : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
    const std::string name =
        "FourBar/NewtonTolerance/" + std::to_string(static_cast<int>(std::lround(-std::log10(tolerance))));
    benchmark::RegisterBenchmark(name.c_str(), sweepBenchmark, newton, thesis().omega,
                                 SolveRequest{true, true, {tolerance, 50}})
        ->Arg(3600)
        ->Unit(benchmark::kNanosecond);
  }
  auto* forces = benchmark::RegisterBenchmark("FourBar/Forces", forcesBenchmark);
  for (const std::int64_t n : kSizes) forces->Arg(n);
  forces->Unit(benchmark::kNanosecond);
  auto* hand = benchmark::RegisterBenchmark("FourBar/HandWritten", handWrittenBenchmark<false>);
  for (const std::int64_t n : kSizes) hand->Arg(n);
  hand->Unit(benchmark::kNanosecond);
  auto* handFull = benchmark::RegisterBenchmark("FourBar/HandWrittenFull", handWrittenBenchmark<true>);
  for (const std::int64_t n : kSizes) handFull->Arg(n);
  handFull->Unit(benchmark::kNanosecond);
  const FourBarSubject& t = thesis();
  benchmark::RegisterBenchmark("FourBar/Pose/Full", poseBenchmark, makeFourBar(t.lengths, t.branch).value(), t.omega)
      ->Unit(benchmark::kNanosecond);
}

}  // namespace

int main(int argc, char** argv) {
  if (!handWrittenMatchesCore()) return 1;
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
