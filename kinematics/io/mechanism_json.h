#pragma once
// Any Mechanism as the members of a document's "mechanism" object (document version 2):
// points in solve order, each with a "type" and its defining numbers, links and distance
// constraints, all referring to points and links by name. Angles are stored in radians
// ("_rad") so a round trip is exact; lengths in the mechanism's length unit.
//
//   "points": [
//     {"name": "O2", "type": "ground", "x": 0, "y": 0},
//     {"name": "B", "type": "crank", "pivot": "O2", "length": 25, "phase_rad": 0},
//     {"name": "C", "type": "rrr", "first": "B", "first_length": 70, "second": "O4",
//      "second_length": 45, "branch": "open"},
//     {"name": "S", "type": "rrp", "first": "B", "length": 150, "branch": "open",
//      "guide": {"link": "rocker", "x": 0, "y": 0, "angle_rad": 0}},   (no "link": ground)
//     {"name": "D", "type": "rpr", "pivot": "O4", "through": "B", "length": 400},
//     {"name": "Q", "type": "prp", "first_guide": {…}, "second_guide": {…}},
//     {"name": "P", "type": "attached", "link": "coupler", "along": 35, "across": 20},
//     {"name": "E", "type": "free", "x": 80, "y": 40}],                 (x, y: the guess)
//   "links": [{"name": "crank", "first": "O2", "second": "B"}, …],
//   "constraints": [{"first": "E", "second": "F", "length": 20}, …]   (optional)

#include "kinematics/io/json_reader.h"
#include "kinematics/model/mechanism.h"

#include <ostream>

namespace linkwright::kinematics::io {

/// Writes the "points", "links" (and, if any, "constraints") members, each line indented by
/// four spaces, separated by ",\n", without a trailing separator.
void writeMechanismMembers(std::ostream& out, const Mechanism& mechanism);

/// Reads those members of `mech` (`path` is its document path, e.g. "mechanism"). Errors go
/// to `reader`; the result is meaningful only if reader.error stays empty. Structure (order,
/// references, one crank) is checked by the caller with checkMechanism.
Mechanism readMechanismMembers(const JsonValue& mech, const std::string& path, JsonReader& reader);

}  // namespace linkwright::kinematics::io
