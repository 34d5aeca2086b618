#pragma once
// `analyze --format table`: the sweep as an aligned, fixed-decimal table for reading in a
// terminal, like the seeds' printed tables (angles, ω and α of the moving links, and the
// transmission angle; with forces, the joint force sizes, slider normal forces, the driving
// torque or the drive's force along its input, an arm's joint torques and the shaking force).
// CSV remains the format for tools. The column widths come from the header alone, so the
// table is written window by window as the sweep is solved.

#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include <ostream>
#include <vector>

namespace linkwright::cli {

class SweepTableWriter {
public:
  SweepTableWriter(std::ostream& out, const kinematics::Mechanism& mechanism, int decimals = 4)
      : m_out(out), m_mechanism(mechanism), m_decimals(decimals) {}
  /// Writes the rows of `part` (a window of the sweep, or all of it), and the summary
  /// columns of `forces` if given; the header first, with the first window.
  void write(const kinematics::SweepResult& part, const kinematics::ForceSweep* forces = nullptr);

private:
  void writeHeader(const kinematics::SweepResult& part, const kinematics::ForceSweep* forces);

  std::ostream& m_out;
  const kinematics::Mechanism& m_mechanism;
  int m_decimals;
  bool m_headerWritten = false;
  std::vector<kinematics::SweepColumn> m_columns;
  std::vector<kinematics::ForceColumn> m_forceColumns;
  std::vector<int> m_widths;
};

/// Writes the link columns of `result` (and the summary columns of `forces`, if given) with
/// `decimals` digits after the point.
void writeSweepTable(std::ostream& out, const kinematics::Mechanism& mechanism, const kinematics::SweepResult& result,
                     const kinematics::ForceSweep* forces = nullptr, int decimals = 4);

}  // namespace linkwright::cli
