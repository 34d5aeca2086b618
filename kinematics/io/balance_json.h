#pragma once
// A balance as JSON (kinematics/design/balance_request.h), written once for linkwright-cli
// balance --json and Python's Linkage.balance: the method, what was added (counterweights or the
// spring and where its ends went) and what it gains over a crank turn, in SI units and the
// design's length unit.

#include "kinematics/design/balance_request.h"
#include "kinematics/io/json.h"

#include <string>

namespace linkwright::kinematics::io {

/// {method: "counterweights" | "spring" | "spring-search", output, length_unit, ...}: with
/// counterweights, description, counterweights [{link, mass_kg, along, across}], omega_rad_s and
/// before / after {shaking_force_peak_N, shaking_moment_peak_Nm, rms_torque_Nm, peak_torque_Nm,
/// bearing_load_peak_N} (null, and no_turn saying why, where no turn could be run); with a
/// spring, spring {first, second, stiffness_N_m, free_length, preload_N}, omega_rad_s,
/// rms_torque_before_Nm and rms_torque_after_Nm, and searched, on_link {point, along, across},
/// on_frame {point, position}, at_bound. `output` is where the design was written (null: not).
JsonValue balanceJson(const BalanceRun& run, const JsonValue& output);

}  // namespace linkwright::kinematics::io
