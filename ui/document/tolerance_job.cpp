#include "ui/document/tolerance_job.h"

#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

std::function<ToleranceOutcome(const std::atomic<bool>& cancel)> toleranceJob(const k::Design& design,
                                                                              const k::MonteCarloSpec& spec) {
  return [mechanism = design.mechanism, grid = k::designSweepSpec(design), spec](const std::atomic<bool>& cancel) {
    k::RunControl control;
    control.cancel = &cancel;
    auto band = k::toleranceMonteCarlo(mechanism, grid, spec, control);
    if (!band) return ToleranceOutcome{std::nullopt, std::nullopt, band.error()};
    if (control.cancelled()) return ToleranceOutcome{std::nullopt, std::nullopt, k::cancelledError()};
    auto sensitivities = k::sweepSensitivities(mechanism, grid);
    if (!sensitivities) return ToleranceOutcome{std::nullopt, std::nullopt, sensitivities.error()};
    return ToleranceOutcome{std::move(band).value(), std::move(sensitivities).value(), std::nullopt};
  };
}

}  // namespace linkwright::ui
