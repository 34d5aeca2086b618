#pragma once
// The core's machine request (kinematics/dynamics/machine_request.h) as work for the worker
// pool (background_request.h): the Flywheel page asks, the document's layer runs, so no view
// calls the core's run itself.

#include "kinematics/design/design.h"
#include "kinematics/dynamics/machine_request.h"

#include <atomic>
#include <functional>
#include <optional>

namespace linkwright::ui {

/// A machine run's answer, or the core's refusal (ErrorCode::Cancelled when it was stopped).
struct MachineOutcome {
  std::optional<kinematics::MachineRun> run;
  std::optional<kinematics::Error> error;
};

/// The run of `request` on `design`'s mechanism, masses and grid, holding its own copies.
std::function<MachineOutcome(const std::atomic<bool>& cancel)> machineJob(const kinematics::Design& design,
                                                                          const kinematics::MachineRequest& request);

}  // namespace linkwright::ui
