#pragma once
// A four-bar's Roberts–Chebyshev cognates as JSON (kinematics/explore/cognates.h), written once
// for linkwright-cli cognates --json and Python's Linkage.cognates: the coupler point, z, the
// third ground pivot, where they were built, and the original and each cognate with its
// pivots, lengths, class, worst transmission angle and the speed its crank turns at.

#include "kinematics/explore/cognates.h"
#include "kinematics/io/json.h"

#include <array>
#include <optional>
#include <string>

namespace linkwright::kinematics::io {

/// {coupler_point, z [re, im], third_pivot, constructed_at_deg, length_unit, linkages [{name,
/// file, crank_pivot, rocker_pivot, lengths, class, worst_transmission_deg, crank_turns_with,
/// coupler_turns_with, rocker_turns_with, crank_speed_ratio_min, crank_speed_ratio_max}]};
/// `files` are where cognate 1 and 2 were written (null where not).
JsonValue cognatesJson(const CognateSet& set, const std::string& lengthUnit,
                       const std::array<std::optional<std::string>, 2>& files);

}  // namespace linkwright::kinematics::io
