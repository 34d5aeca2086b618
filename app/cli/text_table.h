#pragma once
// `analyze --format table`: the sweep as an aligned, fixed-decimal table for reading in a
// terminal, like the seeds' printed tables (angles, ω and α of the moving links, and the
// transmission angle; with forces, the joint force sizes, slider normal forces, the driving
// torque or the drive's force along its input, an arm's joint torques and the shaking force).
// CSV remains the format for tools.

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <ostream>

namespace linkwright::cli {

/// Writes the link columns of `result` (and the summary columns of `forces`, if given) with
/// `decimals` digits after the point.
void writeSweepTable(std::ostream& out, const kinematics::Mechanism& mechanism, const kinematics::SweepResult& result,
                     const kinematics::ForceSweep* forces = nullptr, int decimals = 4);

}  // namespace linkwright::cli
