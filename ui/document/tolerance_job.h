#pragma once
// The tolerance study (kinematics/tune/tolerance_monte_carlo.h) and the sensitivities beside
// it as work for the worker pool (background_request.h): the Tolerances window asks, the
// document's layer runs, never on the GUI thread.

#include "kinematics/design/design.h"
#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <atomic>
#include <functional>
#include <optional>

namespace linkwright::ui {

/// A study's answer, or the core's refusal (ErrorCode::Cancelled when it was stopped).
struct ToleranceOutcome {
  std::optional<kinematics::MonteCarloResult> band;
  std::optional<kinematics::SweepSensitivities> sensitivities;  ///< at every grid input: the curves
  std::optional<kinematics::SensitivitySummary> summary;        ///< the refined first-order worst cases
  std::optional<kinematics::Error> error;
};

/// The study `spec` asks of `design` over its grid, with the sensitivities, holding its own copies.
std::function<ToleranceOutcome(const std::atomic<bool>& cancel)> toleranceJob(const kinematics::Design& design,
                                                                              const kinematics::MonteCarloSpec& spec);

}  // namespace linkwright::ui
