#include "ui/document/force_cycle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

double peakOf(const k::ForceSweep& f) {
  double peak = 0.0;
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (!f.ok(j)) continue;
    for (const auto& column : f.revolute) peak = std::max(peak, column[j].norm());
    for (const auto& column : f.normal) peak = std::max(peak, std::abs(column[j]));
  }
  return peak;
}

}  // namespace

k::Result<ForceCycle> solveForceCycle(ForceCycleInput input, const std::atomic<bool>* cancel) {
  const auto start = std::chrono::steady_clock::now();
  ForceCycle out;
  out.ownSweep = !input.sweep.has_value();
  if (input.sweep) {
    out.sweep = std::move(*input.sweep);
  } else {
    auto own = k::sweep(input.mechanism, input.spec, input.request);
    if (!own) return own.error();
    out.sweep = std::move(own).value();
  }
  auto forces = k::sweepForces(input.mechanism, input.dynamics, out.sweep, cancel);
  if (!forces) return forces.error();
  out.forces = std::move(forces).value();
  for (std::size_t j = 0; j < out.forces.size(); ++j)
    if (out.sweep.ok(j) && !out.forces.ok(j)) ++out.singularSamples;
  out.peakJointForce = peakOf(out.forces);
  out.shakingPeaks = k::shakingPeaks(input.mechanism, input.dynamics, input.spec, out.forces);
  out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace linkwright::ui
