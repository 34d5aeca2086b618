// Speed of the tolerance study (issue 46: 10⁴ samples of a linkage in under a second). One
// item is one Monte-Carlo sample: a linkage with every dimension moved, swept over the grid
// (position, velocity and acceleration), its columns folded into the band. The counter
// `linkages_per_s` is the throughput; `sensitivities` times the exact sensitivities of the
// whole grid (every dimension, every column) for comparison.
//
// Run (Release): build-tolerance/tests/bench/linkwright_tolerance_benchmark

#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <benchmark/benchmark.h>

#include <cstdlib>

using namespace linkwright::kinematics;

namespace {

// A turn in `samples` inputs at the example's speed.
SweepSpec turn(std::size_t samples) {
  SweepSpec spec;
  spec.toAngle = 2.0 * kPi;
  spec.samples = samples;
  spec.omega = 1.0;
  return spec;
}

Mechanism linkage(int which) {
  switch (which) {
  case 0: return makeFourBar(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
  case 1: return findExample("ls3-engine")->mechanism;
  default: return findExample("watt-ii")->mechanism;
  }
}

const char* linkageName(int which) { return which == 0 ? "four-bar" : which == 1 ? "slider-crank" : "watt-ii"; }

// Args: linkage (0 four-bar with P, 1 slider-crank, 2 Watt II), grid samples, Monte-Carlo samples.
void benchMonteCarlo(benchmark::State& state) {
  const Mechanism m = linkage(static_cast<int>(state.range(0)));
  const SweepSpec spec = turn(static_cast<std::size_t>(state.range(1)));
  const MonteCarloSpec mc{0.05, static_cast<std::size_t>(state.range(2)), kDefaultToleranceSeed};
  for (auto _ : state) {
    const auto r = toleranceMonteCarlo(m, spec, mc);
    if (!r || r->used != mc.samples) std::abort();
    benchmark::DoNotOptimize(r->bands.data());
  }
  state.SetLabel(linkageName(static_cast<int>(state.range(0))));
  state.counters["linkages_per_s"] = benchmark::Counter(
      static_cast<double>(mc.samples) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void benchSensitivities(benchmark::State& state) {
  const Mechanism m = linkage(static_cast<int>(state.range(0)));
  const SweepSpec spec = turn(static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(sweepSensitivities(m, spec));
  state.SetLabel(linkageName(static_cast<int>(state.range(0))));
}

}  // namespace

BENCHMARK(benchMonteCarlo)
    ->Args({0, 37, 10000})
    ->Args({0, 361, 10000})
    ->Args({1, 37, 10000})
    ->Args({2, 37, 10000})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(benchSensitivities)->Args({0, 361})->Args({2, 361})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
