#pragma once
// The Linkwright document: a Design as JSON, with a format name and a version so that a file
// from a newer Linkwright is refused with a clear message instead of misread. Every design is
// written as "type": "linkage" (its points, links and constraints: mechanism_json.h), version 2,
// version 3 when it carries "dynamics" (masses and loads, dynamics_json.h), version 4 when its
// crank follows a motion law in time ("driver.law", law_json.h, with "analysis.from_time_s"
// and "to_time_s"), version 5 when it is driven other than by a crank, version 6 when it keeps
// the targets it was synthesised for ("synthesis", synthesis_json.h). Version 1 and 2
// files that hold a four-bar by its lengths ("type": "four-bar") still read, into the mechanism
// makeFourBar builds, so they analyse as before and re-save in the linkage form.
//
//   { "format": "linkwright", "version": 2,
//     "mechanism": { "type": "linkage", "kind": "four-bar", "length_unit": "mm",
//                    "points": [ … ], "links": [ … ], "constraints": [] },
//     "driver": { "omega_rad_s": 1.0471975511965976, "alpha_rad_s2": 0 },
//     "analysis": { "from_deg": 0, "to_deg": 360, "samples": 721 },
//     "dynamics": { "links": {"crank": {"mass_kg": 0.2}}, … } }         (optional, version 3)
//
//   the older four-bar form: "mechanism": { "type": "four-bar", "length_unit": "mm",
//     "branch": "open", "lengths": {"frame": 60, "crank": 25, "coupler": 70, "rocker": 45},
//     "coupler_point": {"along": 35, "across": 20} }                     (coupler_point optional)
//
// Numbers are written in shortest round-trip form, so save → open reproduces the design bit
// for bit. Unknown members are ignored (a newer minor writer may add some); a missing or
// mistyped member is an error naming its path ("mechanism.lengths.coupler").

#include "kinematics/design/design.h"
#include "kinematics/model/result.h"

#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// The newest document version this build reads, and writes for a design that keeps synthesis
/// targets (one driven other than by a crank is written as version 5, one with a motion law as
/// version 4, one with dynamics only as version 3, one with none of these as version 2).
inline constexpr int kDocumentVersion = 7;

/// The document text for a design (UTF-8, LF line ends, trailing newline).
std::string writeDocument(const Design& design);

/// Parses and validates a document. Errors name the member and the reason, e.g.
/// "mechanism.lengths.coupler must be positive and finite (got -70)" or "this file is
/// document version 4, written by a newer Linkwright; this one reads up to version 3".
Result<Design> readDocument(std::string_view text);

}  // namespace linkwright::kinematics::io
