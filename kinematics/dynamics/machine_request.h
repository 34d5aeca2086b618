#pragma once
// `machine` as one request for every front end (request_field.h): its fields, checked once;
// the run that chooses the turn's grid for a stated accuracy; and nothing else. The CLI's
// `machine`, Python's Linkage.machine and the designer's Flywheel page fill the same request
// from their options, keywords and fields, and so give the same figures to the bit.
//
// The grid: one full turn from the design's grid start, at the design's speed (or the one
// asked). Unless `samples` is given, the turn is read at 360 intervals, then 720, 1440, … until
// every figure's error estimate (machine_duty.h: the same figure off every other sample) is
// within `tolerance`, or the most a turn holds (kMaxTurnSamples) is reached; then the duty
// says it did not converge, and its accuracy says by how much. A linkage that turns smoothly
// converges at the first grid: the series' error falls faster than any power of 1/N.

#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/model/request_field.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// The relative accuracy every figure is computed to unless asked otherwise.
inline constexpr double kMachineTolerance = 1e-9;
/// The intervals of the first grid the run reads a turn at.
inline constexpr std::size_t kMachineFirstIntervals = 360;

/// What a turn's duty is asked for.
struct MachineRequest {
  std::optional<double> omega;         ///< rad/s; else the design's
  std::optional<std::size_t> samples;  ///< over the turn, both ends counted; else chosen for `tolerance`
  double tolerance = kMachineTolerance;
  DutyOptions duty;
  FrontEnd frontEnd = FrontEnd::Cli;  ///< who asked: the spelling of the fields in refusals
};

/// machine's fields, in the order front ends list them: rpm, omega, samples, tolerance, cs,
/// gear_ratio, efficiency, rated_torque, rated_speed.
const std::vector<RequestField>& machineFields();

/// The request `given` describes, each value checked against its field (refusals spelled for
/// `frontEnd`); rpm and omega are one speed, not both.
Result<MachineRequest> machineRequest(const RequestValues& given, FrontEnd frontEnd);

/// What the design brings: the crank's speed and where its grid starts.
struct MachineDefaults {
  double omega = 1.0;      ///< rad/s
  double fromAngle = 0.0;  ///< rad
  bool timeBase = false;   ///< the crank follows a motion law in time: its speed must be asked for
};

/// A converged duty, and the grid it was read off.
struct MachineRun {
  MachineDuty duty;
  std::size_t samples = 0;  ///< of the turn read, both ends counted
  bool converged = true;    ///< every figure's estimate within the tolerance (false where none was made)
  double tolerance = kMachineTolerance;
};

/// The duty the request asks for (above); refused on a time base without a speed asked for. `control.progress` gets the grids read (done, of the
/// most there may be); `control.cancel` stops it with ErrorCode::Cancelled.
Result<MachineRun> runMachine(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                              const MachineDefaults& defaults, const MachineRequest& request,
                              const RunControl& control = {});

}  // namespace linkwright::kinematics
