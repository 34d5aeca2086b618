#pragma once
// Writes a sweep as an RFC 4180 CSV table (CRLF line ends, one header row, quoted fields only
// where needed), numbers in shortest round-trip form with '.' whatever the locale. The
// columns and their unit-carrying names are those of sweep_columns.h. Samples that could not
// be assembled are left out; at a singular (toggle) sample the rate cells are empty, never NaN.
// With a force sweep, its columns (force_columns.h) follow, empty where forces are undefined.

#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include <ostream>
#include <string>
#include <vector>

namespace linkwright::kinematics::io {

/// The header names, in column order, for this mechanism and request.
std::vector<std::string> sweepCsvHeader(const Mechanism& mechanism, const SolveRequest& request);

/// Writes a sweep's table as it is solved, window by window (sweepInWindows): the header with
/// the first window, then each window's rows, byte for byte the table writeSweepCsv writes of
/// the whole sweep.
class SweepCsvWriter {
public:
  SweepCsvWriter(std::ostream& out, const Mechanism& mechanism) : m_out(out), m_mechanism(mechanism) {}
  /// Writes the rows of `part` (a window of a sweep of the mechanism, or a whole one), with
  /// the force columns of `forces` (sweepForces of that window) if given.
  void write(const SweepResult& part, const ForceSweep* forces = nullptr);

private:
  std::ostream& m_out;
  const Mechanism& m_mechanism;
  bool m_headerWritten = false;
  std::vector<SweepColumn> m_columns;
  std::vector<ForceColumn> m_forceColumns;
  std::string m_row;
};

/// Writes header and rows. `result` must come from sweep(mechanism, ...).
void writeSweepCsv(std::ostream& out, const Mechanism& mechanism, const SweepResult& result);

/// The same, followed by the force columns of `forces` (sweepForces(mechanism, …, result)).
void writeSweepCsv(std::ostream& out, const Mechanism& mechanism, const SweepResult& result, const ForceSweep& forces);

/// Quotes a field per RFC 4180 if it contains a comma, quote, CR or LF.
std::string csvField(const std::string& text);

}  // namespace linkwright::kinematics::io
