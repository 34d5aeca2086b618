#pragma once
// What a sweep found besides its rows, as the sentences linkwright-cli analyze writes on
// stderr and the Python module raises as SweepWarning: the samples that cannot be assembled
// (their rows left out, with a four-bar's exact assembly range), toggle positions (their rates
// left empty) and locks between samples. One builder, so the two front ends say the same.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

/// An input value in the driver's display unit: "30°" for a crank, "12 mm" for a linear driver.
std::string inputValueText(const Mechanism& mechanism, double q);

/// "crank angles", "tip path positions", "actuator A–C lengths".
std::string inputsName(const Mechanism& mechanism);

/// "toggle position at crank angle 0°: coupler and rocker are collinear, ω and α are undefined
/// (cells left empty)".
std::string toggleNote(const Mechanism& mechanism, double q);

/// "the linkage locks between crank angles 10° and 11° (…); from 11° on it is assembled afresh
/// on the chosen branches, so points jump there".
std::string lockNote(const Mechanism& mechanism, const AngleRange& step);

/// The samples that cannot be assembled, as sentences each ending in a full stop: how many and
/// where (their rows left out), the first failure's reason, and for a four-bar the crank angles
/// it can be assembled at (exact). Empty when every sample assembled.
std::vector<std::string> notAssembledNote(const Mechanism& mechanism, const SweepSummary& summary);

/// All of a sweep's notes, in the order linkwright-cli analyze writes them: toggles, locks, then
/// the samples left out (its sentences joined by spaces). Empty when the sweep went cleanly.
std::vector<std::string> sweepNoteSentences(const Mechanism& mechanism, const SweepSummary& summary);

}  // namespace linkwright::kinematics
