#pragma once
// The Linkwright document: a Design (a parametric four-bar, or any linkage) as JSON, with a
// format name and a version so that a file from a newer Linkwright is refused with a clear
// message instead of misread. Version 1 held four-bars only; version 2 adds
// "type": "linkage" (see mechanism_json.h for its points, links and constraints); version 3
// adds the optional "dynamics" (masses and loads, dynamics_json.h). Older files read
// unchanged, and a design without dynamics is still written as version 2.
//
//   { "format": "linkwright", "version": 2,
//     "mechanism": { "type": "four-bar", "length_unit": "mm", "branch": "open",
//                    "lengths": {"frame": 60, "crank": 25, "coupler": 70, "rocker": 45},
//                    "coupler_point": {"along": 35, "across": 20} },        (optional)
//     "driver": { "omega_rad_s": 1.0471975511965976, "alpha_rad_s2": 0 },
//     "analysis": { "from_deg": 0, "to_deg": 360, "samples": 721 },
//     "dynamics": { "links": {"crank": {"mass_kg": 0.2}}, … } }         (optional, version 3)
//
// Numbers are written in shortest round-trip form, so save → open reproduces the design bit
// for bit. Unknown members are ignored (a newer minor writer may add some); a missing or
// mistyped member is an error naming its path ("mechanism.lengths.coupler").

#include "kinematics/design/mechanism_design.h"
#include "kinematics/model/result.h"

#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// The newest document version this build reads, and writes for a design with dynamics
/// (a design without them is written as version 2).
inline constexpr int kDocumentVersion = 3;

/// The document text for a design (UTF-8, LF line ends, trailing newline).
std::string writeDocument(const Design& design);

/// Parses and validates a document. Errors name the member and the reason, e.g.
/// "mechanism.lengths.coupler must be positive and finite (got -70)" or "this file is
/// document version 4, written by a newer Linkwright; this one reads up to version 3".
Result<Design> readDocument(std::string_view text);

}  // namespace linkwright::kinematics::io
