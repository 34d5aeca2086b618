#pragma once
// The accuracy study's rows (kinematics/design/accuracy_study.h) as linkwright-cli accuracy
// writes them: CSV, errors to 3 significant digits, times to 4. Written once, for the CLI and
// Python.

#include "kinematics/design/accuracy_study.h"

#include <string>
#include <vector>

namespace linkwright::kinematics::io {

/// The columns, with their units: example, method, samples_per_rev, time_us, the relative
/// errors, angle_error_deg, reference.
std::vector<std::string> accuracyColumns();

/// CSV (CRLF rows).
std::string accuracyCsv(const std::vector<AccuracyRow>& rows);

}  // namespace linkwright::kinematics::io
