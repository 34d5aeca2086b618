#pragma once
// A measured θ(t) for a table law, read from a CSV file in the format `linkwright-cli
// --law-table` reads: a header naming the time in s and the angle in degrees or radians
// ("time_s,crank_angle_deg"), then one "time,angle" row per instant. The spline is fitted by
// the core (makeTableLaw), which also checks the rows.
// (The CLI's reader lives in app/cli; both should move to kinematics/io, where the GUI and the
// CLI would share one.)

#include "kinematics/solve/motion_law.h"

#include <QString>

#include <variant>

namespace linkwright::ui {

/// The table law in the file at `path`, or a sentence saying which line is wrong and why.
std::variant<kinematics::TableLaw, QString> readLawTableFile(const QString& path);

}  // namespace linkwright::ui
