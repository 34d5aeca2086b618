#pragma once
// Choosing atlas cells by what their curves have (coupler_atlas.h): a filter is the set of
// features a cell must all have, a plain value the designer's checkboxes and the CLI's
// --filter both make, and matching it is a plain function of a classified cell.

#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/model/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// The features a cell must have; none asked: every cell matches, even one that never assembles.
struct AtlasFilter {
  bool cusp = false;
  bool crunode = false;
  bool symmetric = false;
  bool straight = false;
  bool circular = false;
  bool operator==(const AtlasFilter&) const = default;
};

/// True if `features` has every feature `filter` asks for.
bool matchesFilter(const CurveFeatures& features, const AtlasFilter& filter);

/// True if nothing is asked, or the cell assembles and its curve matches.
bool matchesFilter(const AtlasCell& cell, const AtlasFilter& filter);

/// The indices into `cells` of those that match, in order.
std::vector<std::size_t> filterCells(const std::vector<AtlasCell>& cells, const AtlasFilter& filter);

/// A comma-separated list of "cusp", "crunode", "symmetric", "straight", "circular" as a
/// filter. Error (field `field`) naming the word that is none of them.
Result<AtlasFilter> parseAtlasFilter(const std::string& text, const std::string& field = "filter");

/// The names of the features `features` has, in the order above ("cusp", …).
std::vector<std::string> featureNames(const CurveFeatures& features);

}  // namespace linkwright::kinematics
