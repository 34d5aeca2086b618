#pragma once
// A linkage's inversions as JSON (kinematics/analysis/inversions.h), written once for
// linkwright-cli inversions --json and Python's Linkage.inversions: the chain, the length
// unit, and each inversion's grounded and driven links, class and which links turn fully.

#include "kinematics/analysis/inversions.h"
#include "kinematics/io/json.h"

#include <string>

namespace linkwright::kinematics::io {

/// {linkage: "four-bar" | "slider-crank", length_unit, inversions: [...]}; a four-bar's each
/// {grounded, driven, lengths [frame, crank, coupler, rocker], class, name, driven_turns_fully,
/// output_turns_fully}, a slider-crank's each {grounded, name, driven, driven_turns_fully,
/// output_turns_fully, built, note}.
JsonValue inversionsJson(const LinkageInversions& inversions, const std::string& lengthUnit);

}  // namespace linkwright::kinematics::io
