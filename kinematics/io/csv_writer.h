#pragma once
// Writes a sweep as an RFC 4180 CSV table (CRLF line ends, one header row, quoted fields only
// where needed), numbers in shortest round-trip form with '.' whatever the locale. The
// columns and their unit-carrying names are those of sweep_columns.h. Samples that could not
// be assembled are left out; at a singular (toggle) sample the rate cells are empty, never NaN.
// With a force sweep, its columns (force_columns.h) follow, empty where forces are undefined.

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <ostream>
#include <string>
#include <vector>

namespace linkwright::kinematics::io {

/// The header names, in column order, for this mechanism and request.
std::vector<std::string> sweepCsvHeader(const Mechanism& mechanism, const SolveRequest& request);

/// Writes header and rows. `result` must come from sweep(mechanism, ...).
void writeSweepCsv(std::ostream& out, const Mechanism& mechanism, const SweepResult& result);

/// The same, followed by the force columns of `forces` (sweepForces(mechanism, …, result)).
void writeSweepCsv(std::ostream& out, const Mechanism& mechanism, const SweepResult& result, const ForceSweep& forces);

/// Quotes a field per RFC 4180 if it contains a comma, quote, CR or LF.
std::string csvField(const std::string& text);

}  // namespace linkwright::kinematics::io
