#pragma once
// The mapping a table's headers propose, for File ▸ Compare… to start from and for the CLI to
// suggest when --map is missing. Only clear headers propose anything:
// - analyze's own column names ("rocker_omega_rad_s", "time_s"; "crank_angle_deg" is the x);
// - one symbol with a link's number in the textbooks' numbering (1 the frame, 2 the crank,
//   3 the coupler, 4 the rocker; Norton, Design of Machinery, ch. 4): θ2 (theta2, θ_2) is the
//   crank angle, the x; θ3, θ4, ω3, ω4, α3, α4 are the coupler's and rocker's angle, angular
//   velocity and acceleration, when the linkage has those quantities;
// - "crank angle" (the x) and "time" or "t" (the x in time, when no crank angle is found).
// The unit is the one the header names ("(deg)", "[rad/s]", ", rad/s ²", "deg/sec**2"), else
// the quantity's first unit; a header naming a unit that does not fit, or two symbols, proposes
// nothing. Signs, magnitudes and reversed angles are never guessed.

#include "kinematics/compare/column_mapping.h"

namespace linkwright::kinematics::compare {

/// The mapping `table`'s headers propose for `mechanism` (possibly without an x, or empty).
ColumnMapping proposeColumnMapping(const io::NumericTable& table, const Mechanism& mechanism);

}  // namespace linkwright::kinematics::compare
