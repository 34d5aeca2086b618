#include "ui/document/machine_job.h"

#include "kinematics/design/sweep_grid.h"

#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

std::function<MachineOutcome(const std::atomic<bool>& cancel)> machineJob(const k::Design& design,
                                                                          const k::MachineRequest& request) {
  return [mechanism = design.mechanism, dynamics = design.dynamics,
          defaults = k::machineDefaultsOf(k::sweepGridOf(design)), request](const std::atomic<bool>& cancel) {
    k::RunControl control;
    control.cancel = &cancel;
    auto run = k::runMachine(mechanism, dynamics, defaults, request, control);
    return run ? MachineOutcome{std::move(run).value(), std::nullopt} : MachineOutcome{std::nullopt, run.error()};
  };
}

}  // namespace linkwright::ui
