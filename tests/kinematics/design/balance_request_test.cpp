// The balance request's before and after (kinematics/design/balance_request.h): converged as
// machine's figures are, not read off the design's own grid; checked against the same figures
// on a turn forty times as fine, and against the machine request run alone.

#include "kinematics/design/balance_request.h"

#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/machine_request.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;

namespace {

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

void checkAgainstDense(const Design& design, const MachineDuty& duty, const LinkageDynamics& dynamics) {
  SweepSpec dense = designTurn(design);
  dense.samples = 14401;
  const auto reference = machineDuty(design.mechanism, dynamics, dense, {});
  REQUIRE(reference.ok());
  CHECK(relative(duty.peakTorque, reference->peakTorque) < 1e-9);
  CHECK(relative(duty.rmsTorque, reference->rmsTorque) < 1e-9);
  // Balanced, the shaking force is zero to round-off: within 1e-9 of the bearing loads.
  CHECK(std::abs(duty.shakingForcePeak - reference->shakingForcePeak) <
        1e-9 * std::max(reference->shakingForcePeak, reference->bearingLoadPeak));
  CHECK(relative(duty.bearingLoadPeak, reference->bearingLoadPeak) < 1e-9);
}

}  // namespace

TEST_CASE("balance's before and after are machine's converged figures", "[balance][request]") {
  const auto design = designForExample("funsho-fourbar");
  REQUIRE(design);
  const auto run = runBalance(*design, {});
  REQUIRE(run.ok());
  REQUIRE(run->before);
  REQUIRE(run->after);
  // Both turns converge on the first grid: the balanced shaking force, zero to round-off, is
  // measured against the bearing loads (it never converged against itself).
  CHECK(run->converged);
  CHECK(run->turnSamples == kMachineFirstIntervals + 1);
  CHECK(run->before->worstAccuracy() <= kMachineTolerance);
  CHECK(run->after->worstAccuracy() <= kMachineTolerance);
  // The same request machine answers, to the bit.
  const auto machine = runMachine(design->mechanism, design->dynamics, machineDefaultsOf(sweepGridOf(*design)), {});
  REQUIRE(machine.ok());
  CHECK(run->before->peakTorque == machine->duty.peakTorque);
  CHECK(run->before->shakingForcePeak == machine->duty.shakingForcePeak);
  // And within 1e-9 of a turn forty times as fine, before and after.
  checkAgainstDense(*design, *run->before, design->dynamics);
  checkAgainstDense(*design, *run->after, run->balanced.dynamics);
  // The counterweights do what they are for.
  CHECK(run->after->shakingForcePeak < run->before->shakingForcePeak);
}
