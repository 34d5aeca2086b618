#pragma once
// A measured q(t) for a table law, read from a CSV file by the core's reader
// (kinematics/io/law_table_csv.h, which the CLI's --law-table uses too): a header naming the
// time in s and the position with its unit (a crank's angle in _deg or _rad, a linear driver's
// position in the linkage's length unit), then one "time,position" row per instant.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/motion_law.h"

#include <QString>

#include <variant>

namespace linkwright::ui {

/// The table law in the file at `path` for `mechanism`'s driver, or a sentence naming the
/// file and saying which line is wrong and why.
std::variant<kinematics::TableLaw, QString> readLawTableFile(const QString& path,
                                                             const kinematics::Mechanism& mechanism);

}  // namespace linkwright::ui
