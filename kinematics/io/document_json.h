#pragma once
// The Linkwright document: a Design (a parametric four-bar, or any linkage) as JSON, with a
// format name and a version so that a file from a newer Linkwright is refused with a clear
// message instead of misread. Version 1 held four-bars only; version 2 adds
// "type": "linkage" (see mechanism_json.h for its points, links and constraints). A version 1
// file reads unchanged: its four-bar is the same in version 2.
//
//   { "format": "linkwright", "version": 2,
//     "mechanism": { "type": "four-bar", "length_unit": "mm", "branch": "open",
//                    "lengths": {"frame": 60, "crank": 25, "coupler": 70, "rocker": 45},
//                    "coupler_point": {"along": 35, "across": 20} },        (optional)
//     "driver": { "omega_rad_s": 1.0471975511965976, "alpha_rad_s2": 0 },
//     "analysis": { "from_deg": 0, "to_deg": 360, "samples": 721 } }
//
// Numbers are written in shortest round-trip form, so save → open reproduces the design bit
// for bit. Unknown members are ignored (a newer minor writer may add some); a missing or
// mistyped member is an error naming its path ("mechanism.lengths.coupler").

#include "kinematics/model/mechanism_design.h"
#include "kinematics/model/result.h"

#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// The document version this build writes and the newest it reads.
inline constexpr int kDocumentVersion = 2;

/// The document text for a design (UTF-8, LF line ends, trailing newline).
std::string writeDocument(const Design& design);

/// Parses and validates a document. Errors name the member and the reason, e.g.
/// "mechanism.lengths.coupler must be positive and finite (got -70)" or "this file is
/// document version 3, written by a newer Linkwright; this one reads up to version 2".
Result<Design> readDocument(std::string_view text);

} // namespace linkwright::kinematics::io
