#include "kinematics/io/cognates_json.h"

#include "kinematics/model/units.h"

namespace linkwright::kinematics::io {
namespace {

JsonValue point(const Eigen::Vector2d& p) { return JsonValue::array({p.x(), p.y()}); }

JsonValue optional(const std::optional<double>& v) { return v ? JsonValue(*v) : JsonValue(nullptr); }

}  // namespace

JsonValue cognatesJson(const CognateSet& set, const std::string& unit,
                       const std::array<std::optional<std::string>, 2>& files) {
  JsonValue linkages = JsonValue::array();
  const std::array<const CognateFourBar*, 3> bars{&set.original, &set.cognates[0], &set.cognates[1]};
  for (std::size_t i = 0; i < 3; ++i) {
    const CognateFourBar& f = *bars[i];
    const FourBarLengths& l = f.fourBar.lengths;
    const std::optional<std::string> file = i == 0 ? std::nullopt : files[i - 1];
    linkages.push_back(
        {{"name", i == 0 ? std::string("original") : "cognate " + std::to_string(i)},
         {"file", file ? JsonValue(*file) : JsonValue(nullptr)},
         {"crank_pivot", point(f.crankPivot)},
         {"rocker_pivot", point(f.rockerPivot)},
         {"lengths", {{"frame", l.frame}, {"crank", l.crank}, {"coupler", l.coupler}, {"rocker", l.rocker}}},
         {"class", toString(f.grashof.category)},
         {"worst_transmission_deg",
          f.worstTransmission ? JsonValue(radToDeg(*f.worstTransmission)) : JsonValue(nullptr)},
         {"crank_turns_with", toString(f.turnsWith[0])},
         {"coupler_turns_with", toString(f.turnsWith[1])},
         {"rocker_turns_with", toString(f.turnsWith[2])},
         {"crank_speed_ratio_min", optional(f.crankSpeedRatioMin)},
         {"crank_speed_ratio_max", optional(f.crankSpeedRatioMax)}});
  }
  return {{"coupler_point", set.couplerPoint},
          {"z", {set.z.real(), set.z.imag()}},
          {"third_pivot", point(set.thirdPivot)},
          {"constructed_at_deg", radToDeg(set.constructedAt)},
          {"length_unit", unit},
          {"linkages", linkages}};
}

}  // namespace linkwright::kinematics::io
