#pragma once
// Writes a sweep as an RFC 4180 CSV table (CRLF line ends, one header row, quoted fields only
// where needed), numbers in shortest round-trip form with '.' whatever the locale. Every
// column name carries its unit:
//   crank_angle_deg                    the input angle (the sweep's grid)
//   <link>_angle_deg                   each moving link other than the driven crank, unwrapped
//   <link>_omega_rad_s, <link>_alpha_rad_s2   each moving link, crank first
//   transmission_angle_deg             per RRR dyad (suffixed _<point> when there are several)
//   <point>_x_<unit>, _y_, _vx_<unit>_s, _vy_, _ax_<unit>_s2, _ay_   each moving point
// Columns for quantities not requested are left out. Samples that could not be assembled are
// left out; at a singular (toggle) sample the rate cells are empty, never NaN.

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

/// Quotes a field per RFC 4180 if it contains a comma, quote, CR or LF.
std::string csvField(const std::string& text);

} // namespace linkwright::kinematics::io
