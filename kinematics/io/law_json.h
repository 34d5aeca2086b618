#pragma once
// A motion law (solve/motion_law.h) as the document's "driver.law" member, and back:
//   {"type": "constant",  "start_rad": 0, "velocity_rad_s": 1.0471975511965976}
//   {"type": "ramp",      "start_rad": 0, "velocity_rad_s": 1.05, "ramp_time_s": 2}
//   {"type": "cycloidal", "start_rad": 0, "rise_rad": 1.5707963267948966, "duration_s": 0.5}
//   {"type": "345",       (as cycloidal)}
//   {"type": "table",     "time_s": [0, 0.5, …], "angle_rad": [0, 0.1, …]}   (≥ 4 rows)
// Numbers in shortest round-trip form, so a law reads back bit for bit.

#include "kinematics/io/json.h"
#include "kinematics/io/json_reader.h"
#include "kinematics/solve/motion_law.h"

#include <optional>
#include <ostream>
#include <string>

namespace linkwright::kinematics::io {

/// Writes `law` as a JSON object.
void writeLaw(std::ostream& out, const MotionLaw& law);

/// Reads the law at `value` (an object); errors go to `r`, naming `path` and the member.
std::optional<MotionLaw> readLaw(const JsonValue& value, const std::string& path, JsonReader& r);

}  // namespace linkwright::kinematics::io
