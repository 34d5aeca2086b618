#pragma once
// A design's synthesis targets (design/synthesis_targets.h) as the document's "synthesis"
// member, and back. Angles in radians and lengths in the design's length unit, each key
// naming its unit, numbers in shortest round-trip form so a document reads back bit for bit:
//   "synthesis": {"problem": "swing",
//     "swing": {"swing_rad": 1.0471975511965976, "time_ratio": 1.3, "length": 50, "fixed": "rocker"},
//     "slider": {"stroke": 100, "time_ratio": 1.2, "fixed": "rod", "value": 150},
//     "shaper": {"stroke": 300, "time_ratio": 1.5, "crank": 50, "link": 150},   ("guide_height")
//     "function": {"name": "log10", "x0": 1, "x1": 10, "input_start_rad": …, "input_span_rad": …,
//                  "output_start_rad": …, "output_span_rad": …, "frame": 100, "points": [], "count": 3},
//     "motion": {"poses": [{"x": 0, "y": 0, "angle_rad": 0}, …], "circle_point_a": [x, y],
//                "circle_point_b": [x, y], "centre_a": 0, "centre_b": 0, "full_turn": false},
//     "path": {"targets": [[x, y], …], "timing_rad": [], "timing_from": "start", "full_turn": false,
//              "starts": 400, "seed": 19},
//     "bounds": {"min_transmission_rad": 0.6981317007977318, "max_ratio": 10}}   ("max_link")
// A missing optional bound is no bound.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/io/json.h"
#include "kinematics/io/json_reader.h"

#include <optional>
#include <ostream>
#include <string>

namespace linkwright::kinematics::io {

/// Writes `,\n  "synthesis": {…}` (the member and the comma before it).
void writeSynthesisMember(std::ostream& out, const SynthesisTargets& targets);

/// The "synthesis" member of the document `root`, if it has one; errors go to `r`, naming
/// the member's path ("synthesis.swing.time_ratio"). Lengths take `lengthUnit`.
std::optional<SynthesisTargets> readSynthesisMember(const JsonValue& root, const std::string& lengthUnit,
                                                    JsonReader& r);

}  // namespace linkwright::kinematics::io
