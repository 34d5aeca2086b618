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
    if (!band) return ToleranceOutcome{.error = band.error()};
    if (control.cancelled()) return ToleranceOutcome{.error = k::cancelledError()};
    auto sensitivities = k::sweepSensitivities(mechanism, grid);
    if (!sensitivities) return ToleranceOutcome{.error = sensitivities.error()};
    auto summary = k::sensitivitySummary(mechanism, grid, k::dimensionTolerances(spec, band->dimensions), control);
    if (!summary) return ToleranceOutcome{.error = summary.error()};
    return ToleranceOutcome{std::move(band).value(), std::move(sensitivities).value(), std::move(summary).value(),
                            std::nullopt};
  };
}

}  // namespace linkwright::ui
