#pragma once
// A measured motion, q(t), for a table law (solve/motion_law.h), from CSV text: a header
// naming the time in s and the position with its unit, then one "time,position" row per
// instant. A crank's angle is in degrees or radians ("time_s,crank_angle_deg", "_rad"); a
// linear driver's position is in the linkage's length unit ("time_s,tip_s_mm"). The CLI's
// --law-table and the designer's Drive panel read tables through here, so both accept the
// same files and say the same about a wrong one.

#include "kinematics/model/driver.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/motion_law.h"

#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// A measurement is far smaller; the bound keeps a wrong file (a device, an image) out.
inline constexpr std::size_t kMaxLawTableBytes = 64u << 20;

/// The table law in `text`, for a driver of `kind` in `lengthUnit`; an Error naming the line
/// and what is wrong (a header without the time and the position's unit, a row that is not two
/// numbers, or what makeTableLaw refuses).
Result<TableLaw> readLawTableCsv(std::string_view text, InputKind kind, const std::string& lengthUnit);

}  // namespace linkwright::kinematics::io
