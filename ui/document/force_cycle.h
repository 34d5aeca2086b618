#pragma once
// One solve of the forces over the displayed cycle, from plain data to plain data, so that the
// very same function runs in the GUI thread or in a worker (force_results.h chooses): the
// worker's results are the synchronous ones by construction, and the tests check it.

#include "kinematics/dynamics/force_extrema.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <atomic>
#include <cstddef>
#include <optional>

namespace linkwright::ui {

/// What a cycle solve needs, copied from the document (a worker must not read it).
struct ForceCycleInput {
  kinematics::Mechanism mechanism;
  kinematics::LinkageDynamics dynamics;
  /// The document's sweep, if it holds every acceleration; else the grid and request to
  /// sweep here first.
  std::optional<kinematics::SweepResult> sweep;
  kinematics::SweepSpec spec;
  kinematics::SolveRequest request;
};

/// The forces over the cycle and the kinematic sweep they were solved on.
struct ForceCycle {
  kinematics::SweepResult sweep;
  kinematics::ForceSweep forces;
  bool ownSweep = false;            ///< `sweep` was made here (the document's lacked accelerations)
  std::size_t singularSamples = 0;  ///< samples whose kinematics are Ok but forces are not determined
  double peakJointForce = 0.0;      ///< N, |F| of revolute joints and |N| of prismatic ones
  /// The shaking force's and moment's peaks, refined between samples (force_extrema.h); none
  /// when no sample's forces are solved
  std::optional<kinematics::ShakingPeaks> shakingPeaks;
  double milliseconds = 0.0;  ///< wall time the solve took
};

/// Solves `input`; stops with ErrorCode::Cancelled once `cancel` (if given) becomes true.
kinematics::Result<ForceCycle> solveForceCycle(ForceCycleInput input, const std::atomic<bool>* cancel = nullptr);

}  // namespace linkwright::ui
