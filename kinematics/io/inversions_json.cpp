#include "kinematics/io/inversions_json.h"

namespace linkwright::kinematics::io {

JsonValue inversionsJson(const LinkageInversions& inversions, const std::string& unit) {
  JsonValue all = JsonValue::array();
  if (inversions.fourBar) {
    for (const FourBarInversion& inv : inversions.fourBars)
      all.push_back({{"grounded", toString(inv.grounded)},
                     {"driven", toString(inv.driven)},
                     {"lengths", {inv.lengths.frame, inv.lengths.crank, inv.lengths.coupler, inv.lengths.rocker}},
                     {"class", toString(inv.grashof.category)},
                     {"name", inv.name},
                     {"driven_turns_fully", inv.grashof.inputFullyRotates},
                     {"output_turns_fully", inv.grashof.outputFullyRotates}});
    return {{"linkage", "four-bar"}, {"length_unit", unit}, {"inversions", all}};
  }
  for (const SliderCrankInversion& inv : inversions.sliderCranks)
    all.push_back({{"grounded", toString(inv.grounded)},
                   {"name", inv.name},
                   {"driven", inv.driven},
                   {"driven_turns_fully", inv.driverTurnsFully},
                   {"output_turns_fully", inv.outputTurnsFully},
                   {"built", inv.mechanism.has_value()},
                   {"note", inv.note}});
  return {{"linkage", "slider-crank"}, {"length_unit", unit}, {"inversions", all}};
}

}  // namespace linkwright::kinematics::io
