#include "kinematics/explore/atlas_filter.h"

namespace linkwright::kinematics {

bool matchesFilter(const CurveFeatures& f, const AtlasFilter& filter) {
  return (!filter.cusp || !f.cusps.empty()) && (!filter.crunode || !f.crunodes.empty()) &&
         (!filter.symmetric || f.symmetry) && (!filter.straight || f.straight) && (!filter.circular || f.circular);
}

bool matchesFilter(const AtlasCell& cell, const AtlasFilter& filter) {
  return filter == AtlasFilter{} ||
         (cell.motion != CrankMotion::NeverAssembles && matchesFilter(cell.features, filter));
}

std::vector<std::size_t> filterCells(const std::vector<AtlasCell>& cells, const AtlasFilter& filter) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (matchesFilter(cells[i], filter)) out.push_back(i);
  return out;
}

Result<AtlasFilter> parseAtlasFilter(const std::string& text, const std::string& field) {
  AtlasFilter filter;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string word = text.substr(start, comma - start);
    if (word == "cusp") filter.cusp = true;
    else if (word == "crunode") filter.crunode = true;
    else if (word == "symmetric") filter.symmetric = true;
    else if (word == "straight") filter.straight = true;
    else if (word == "circular") filter.circular = true;
    else
      return Error{
          ErrorCode::InvalidValue, field,
          field + " takes cusp, crunode, symmetric, straight or circular, separated by commas (got '" + word + "')"};
    start = comma + 1;
  }
  return filter;
}

std::vector<std::string> featureNames(const CurveFeatures& f) {
  std::vector<std::string> names;
  if (!f.cusps.empty()) names.push_back("cusp");
  if (!f.crunodes.empty()) names.push_back("crunode");
  if (f.symmetry) names.push_back("symmetric");
  if (f.straight) names.push_back("straight");
  if (f.circular) names.push_back("circular");
  return names;
}

}  // namespace linkwright::kinematics
