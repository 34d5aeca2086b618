// Speed of dimensional synthesis (issue 19): each closed-form problem must take well under a
// millisecond; path generation on 6 points must reach a worst distance within 1 % of the
// targets' scale in under 2 s on the 2-core machine. One item is one synthesis call.
// Path benchmarks report, as counters, the best worst distance over the scale
// (`worst_over_scale`), the wall time until a candidate within 1 % was first found
// (`s_to_1pct`, −1 if none was) and how many candidates were kept.
//
// Run (Release): build-synrel/bin/linkwright_synthesis_benchmark

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/synthesis/function_generation.h"
#include "kinematics/synthesis/motion_generation.h"
#include "kinematics/synthesis/path_generation.h"
#include "kinematics/synthesis/stroke_shaper.h"
#include "kinematics/synthesis/stroke_slider_crank.h"
#include "kinematics/synthesis/swing_crank_rocker.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <vector>

using namespace linkwright::kinematics;

namespace {

void benchSwingDefault(benchmark::State& state) {
  const SwingTarget target{degToRad(60.0), 1.3, 50.0};
  for (auto _ : state) benchmark::DoNotOptimize(synthesiseCrankRocker(target));
}

void benchSwingOne(benchmark::State& state) {
  const SwingTarget target{degToRad(60.0), 1.3, 50.0};
  const auto s = synthesiseCrankRocker(target);
  if (!s) std::abort();
  const double parameter = s->best.parameter;
  for (auto _ : state) benchmark::DoNotOptimize(crankRockerAt(target, parameter));
}

void benchSliderCrank(benchmark::State& state) {
  const StrokeTarget target{100.0, 1.3, SliderChoice::Offset, 20.0};
  for (auto _ : state) benchmark::DoNotOptimize(synthesiseSliderCrank(target));
}

void benchShaper(benchmark::State& state) {
  const ShaperTarget target{300.0, 1.5, 60.0, 150.0};
  for (auto _ : state) benchmark::DoNotOptimize(synthesiseShaper(target));
}

// y = log10 x on [1, 10], the textbook generator (as function_generation_test.cpp).
void benchFunction(benchmark::State& state) {
  const FunctionTarget target{[](double x) { return std::log10(x); },
                              1.0,
                              10.0,
                              degToRad(45.0),
                              degToRad(60.0),
                              degToRad(135.0),
                              degToRad(90.0),
                              50.0,
                              "mm"};
  FunctionOptions options;
  options.count = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(synthesiseFunction(target, options));
}

void benchMotion3(benchmark::State& state) {
  const std::vector<CouplerPose> poses{
      {{0.0, 0.0}, 0.0}, {{40.0, 20.0}, degToRad(25.0)}, {{75.0, 15.0}, degToRad(55.0)}};
  const CirclePoints circle{{-20.0, -30.0}, {30.0, -40.0}};
  for (auto _ : state) benchmark::DoNotOptimize(synthesiseMotion3(poses, circle));
}

// The thesis crank-rocker (60/25/70/45 mm) with a coupler point 35 along, 20 across, at six
// crank angles: a path a four-bar passes through exactly.
std::vector<Eigen::Vector2d> thesisTargets() {
  const auto m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0});
  if (!m) std::abort();
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 6; ++k) {
    const auto pose = solvePose(*m, {degToRad(60.0 * k), 0.0, 0.0});
    if (!pose) std::abort();
    points.push_back(pose->position[fourbar::kCouplerPoint.index]);
  }
  return points;
}

// Six points on an ellipse (semi-axes 40 and 20 mm, tilted 30°): not a coupler curve, so
// only an approximate fit exists in general.
std::vector<Eigen::Vector2d> ellipseTargets() {
  std::vector<Eigen::Vector2d> points;
  const double tilt = degToRad(30.0);
  for (int k = 0; k < 6; ++k) {
    const double t = 2.0 * kPi * k / 6.0;
    const Eigen::Vector2d p(40.0 * std::cos(t), 20.0 * std::sin(t));
    points.emplace_back(std::cos(tilt) * p.x() - std::sin(tilt) * p.y(),
                        std::sin(tilt) * p.x() + std::cos(tilt) * p.y());
  }
  return points;
}

// Ten points on the same ellipse: more than the nine a four-bar can pass through in general.
std::vector<Eigen::Vector2d> ellipseTargets10() {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 10; ++k) {
    const double t = 2.0 * kPi * k / 10.0;
    points.emplace_back(40.0 * std::cos(t), 20.0 * std::sin(t));
  }
  return points;
}

void path(benchmark::State& state, const std::vector<Eigen::Vector2d>& targets) {
  PathOptions options;
  if (state.range(0) > 0) options.starts = static_cast<int>(state.range(0));
  double worst = 0.0, toOnePercent = -1.0, kept = 0.0;
  for (auto _ : state) {
    const auto s = synthesisePath({targets}, options);
    if (!s || s->candidates.empty()) std::abort();
    worst = s->candidates.front().worstDistance / s->scale;
    toOnePercent = -1.0;
    for (const PathCandidate& c : s->candidates)
      if (c.worstDistance <= 1e-2 * s->scale && (toOnePercent < 0.0 || c.secondsToFind < toOnePercent))
        toOnePercent = c.secondsToFind;
    kept = static_cast<double>(s->candidates.size());
  }
  state.counters["worst_over_scale"] = worst;
  state.counters["s_to_1pct"] = toOnePercent;
  state.counters["candidates"] = kept;
}

void benchPathThesis(benchmark::State& state) { path(state, thesisTargets()); }
void benchPathEllipse(benchmark::State& state) { path(state, ellipseTargets()); }
void benchPathEllipse10(benchmark::State& state) { path(state, ellipseTargets10()); }

}  // namespace

BENCHMARK(benchSwingDefault)->Name("Swing/Default41AndBest")->Unit(benchmark::kMicrosecond);
BENCHMARK(benchSwingOne)->Name("Swing/One")->Unit(benchmark::kMicrosecond);
BENCHMARK(benchSliderCrank)->Name("SliderCrank/Offset")->Unit(benchmark::kMicrosecond);
BENCHMARK(benchShaper)->Name("Shaper/Stroke")->Unit(benchmark::kMicrosecond);
BENCHMARK(benchFunction)->Name("Function/Points")->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(benchMotion3)->Name("Motion/ThreePoses")->Unit(benchmark::kMicrosecond);
// Arg 0: the default number of starts (kDefaultPathStarts).
BENCHMARK(benchPathThesis)->Name("Path/Thesis6/Starts")->Arg(0)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(benchPathEllipse)
    ->Name("Path/Ellipse6/Starts")
    ->Arg(0)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(benchPathEllipse10)
    ->Name("Path/Ellipse10/Starts")
    ->Arg(0)
    ->Arg(2000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();
