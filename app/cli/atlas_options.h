#pragma once
// `linkwright-cli atlas …`: the coupler-curve atlas's options (kinematics/explore/coupler_atlas.h),
// parsed into a plain request. Every error names the option, the value and the accepted range.

#include "kinematics/explore/atlas_filter.h"
#include "kinematics/explore/coupler_atlas.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::cli {

/// What `atlas` was asked for.
struct AtlasOptions {
  kinematics::AtlasAxes axes;
  kinematics::AtlasFilter filter;
  bool json = false;
  std::optional<std::string> outputFile;  ///< the table as CSV, or with --cell the design document
  std::optional<std::size_t> cell;        ///< --cell I: write that cell's linkage as a document
  double crank = 1.0;                     ///< --crank, the written design's crank length
  std::string lengthUnit = "mm";          ///< --unit
};

/// Parses the arguments after `atlas`. `help` is set when --help or -h is among them.
kinematics::Result<AtlasOptions> parseAtlasArguments(const std::vector<std::string>& args, bool& help);

}  // namespace linkwright::cli
