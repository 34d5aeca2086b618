#pragma once
// A motion law (solve/motion_law.h) as the document's "driver.law" member, and back:
//   {"type": "constant",  "start_rad": 0, "velocity_rad_s": 1.0471975511965976}
//   {"type": "ramp",      "start_rad": 0, "velocity_rad_s": 1.05, "ramp_time_s": 2}
//   {"type": "cycloidal", "start_rad": 0, "rise_rad": 1.5707963267948966, "duration_s": 0.5}
//   {"type": "345",       (as cycloidal)}
//   {"type": "table",     "time_s": [0, 0.5, …], "angle_rad": [0, 0.1, …]}   (≥ 4 rows)
// Numbers in shortest round-trip form, so a law reads back bit for bit. That is a crank's law,
// in radians; a path or actuator driver's law is in the length unit, and its keys say so
// ("start_mm", "velocity_mm_s", "rise_mm", "position_mm"): InputKeys.

#include "kinematics/io/json.h"
#include "kinematics/io/json_reader.h"
#include "kinematics/model/driver.h"
#include "kinematics/solve/motion_law.h"

#include <optional>
#include <ostream>
#include <string>

namespace linkwright::kinematics::io {

/// The document's keys for the driver's numbers, each with its unit: a crank's in degrees
/// and radians, a linear driver's in the mechanism's length unit.
struct InputKeys {
  std::string rate;          ///< driver: "omega_rad_s" or "velocity_<u>_s"
  std::string acceleration;  ///< driver: "alpha_rad_s2" or "acceleration_<u>_s2"
  std::string from;          ///< analysis: "from_deg" or "from_<u>"
  std::string to;            ///< analysis: "to_deg" or "to_<u>"
  std::string lawStart;      ///< law: "start_rad" or "start_<u>"
  std::string lawVelocity;   ///< law: "velocity_rad_s" or "velocity_<u>_s"
  std::string lawRise;       ///< law: "rise_rad" or "rise_<u>"
  std::string lawTable;      ///< law: "angle_rad" or "position_<u>"
};

/// The keys for a driver of this kind (model/driver.h) in a linkage of this length unit.
InputKeys inputKeys(InputKind kind, const std::string& lengthUnit);

/// Writes `law` as a JSON object.
void writeLaw(std::ostream& out, const MotionLaw& law, const InputKeys& keys);

/// Reads the law at `value` (an object); errors go to `r`, naming `path` and the member.
std::optional<MotionLaw> readLaw(const JsonValue& value, const std::string& path, const InputKeys& keys, JsonReader& r);

}  // namespace linkwright::kinematics::io
