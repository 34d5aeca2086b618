// What each synthesis problem needs besides each option's own range: the options it cannot do
// without, the ones that exclude each other, counts (poses, circle points, targets) and where a
// named function is defined. Messages name the options as the user typed them.

#include "app/cli/option_values.h"
#include "app/cli/synthesize_options.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/synthesis/named_function.h"

#include <cmath>
#include <tuple>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::formatNumber;

std::optional<Error> require(bool given, const std::string& option, const std::string& what) {
  if (given) return std::nullopt;
  return usage(option, what + " (see linkwright-cli --help synthesize)");
}

std::optional<Error> checkFunction(const SynthesisRequest& r) {
  const std::pair<bool, const char*> required[] = {{!r.function.empty(), "--function"},
                                                   {r.x0.has_value(), "--x0"},
                                                   {r.x1.has_value(), "--x1"},
                                                   {r.inputStartDeg.has_value(), "--input-start"},
                                                   {r.inputSpanDeg.has_value(), "--input-span"},
                                                   {r.outputStartDeg.has_value(), "--output-start"},
                                                   {r.outputSpanDeg.has_value(), "--output-span"}};
  for (const auto& [given, option] : required)
    if (auto e = require(given, option, std::string("synthesize function needs ") + option)) return e;
  if (!(*r.x1 > *r.x0))
    return usage("--x1", "--x1 must be greater than --x0 (got --x0 " + formatNumber(*r.x0) + ", --x1 " +
                             formatNumber(*r.x1) + ")");
  if (r.points && !r.at.empty()) return usage("--at", "--points and --at cannot be used together");
  if (!r.at.empty() && r.at.size() < 3)
    return usage("--at", "--at needs at least 3 precision points (got " + std::to_string(r.at.size()) + ")");
  for (std::size_t i = 0; i < r.at.size(); ++i) {
    if (r.at[i] < *r.x0 || r.at[i] > *r.x1)
      return usage("--at", "--at: precision point " + formatNumber(r.at[i]) + " must lie in [--x0, --x1] = [" +
                               formatNumber(*r.x0) + ", " + formatNumber(*r.x1) + "]");
    if (i > 0 && !(r.at[i] > r.at[i - 1]))
      return usage("--at", "--at: precision points must be distinct and increasing (got " + formatNumber(r.at[i]) +
                               " after " + formatNumber(r.at[i - 1]) + ")");
  }
  // Where a named function is undefined, say so by the range rather than by a NaN.
  if (auto e = kinematics::checkFunctionRange(*kinematics::findNamedFunction(r.function), *r.x0, *r.x1))
    return usage("--" + e->field, "--" + e->field + ": " + e->message);
  return std::nullopt;
}

std::optional<Error> checkMotion(const SynthesisRequest& r) {
  if (r.poses.size() != 2 && r.poses.size() != 3)
    return usage("--pose", "synthesize motion needs --pose X,Y,DEG two or three times (got " +
                               std::to_string(r.poses.size()) + ")");
  if (r.circlePoints.size() != 2)
    return usage("--circle-point",
                 "synthesize motion needs --circle-point X,Y twice: the crank's moving pivot, "
                 "then the rocker's, at pose 1 (got " +
                     std::to_string(r.circlePoints.size()) + ")");
  if (r.poses.size() == 2 && r.centres.size() != 2)
    return usage("--centre", "two poses need --centre D twice: where each centre point lies on its bisector (got " +
                                 std::to_string(r.centres.size()) + ")");
  if (r.poses.size() == 3 && !r.centres.empty())
    return usage("--centre", "--centre is for two poses; with three the centre points follow from the circle points");
  return std::nullopt;
}

}  // namespace

std::optional<Error> checkSynthesisRequest(const SynthesisRequest& r) {
  switch (r.problem) {
  case SynthesisProblem::Swing:
    if (auto e = require(r.swingDeg.has_value(), "--swing", "synthesize swing needs --swing DEG")) return e;
    if (auto e = require(r.timeRatio.has_value(), "--time-ratio", "synthesize swing needs --time-ratio Q")) return e;
    if (r.rocker && r.frame) return usage("--frame", "--rocker and --frame cannot be used together: fix one of them");
    return require(r.rocker || r.frame, "--rocker", "synthesize swing needs --rocker L or --frame L");
  case SynthesisProblem::Slider:
    if (auto e = require(r.stroke.has_value(), "--stroke", "synthesize slider needs --stroke S")) return e;
    if (auto e = require(r.timeRatio.has_value(), "--time-ratio", "synthesize slider needs --time-ratio Q")) return e;
    if (r.rod && r.offset) return usage("--offset", "--rod and --offset cannot be used together: fix one of them");
    return require(r.rod || r.offset, "--rod", "synthesize slider needs --rod L or --offset E");
  case SynthesisProblem::Shaper:
    for (const auto& [given, option, shape] : {std::tuple{r.stroke.has_value(), "--stroke", "S"},
                                               {r.timeRatio.has_value(), "--time-ratio", "Q"},
                                               {r.crank.has_value(), "--crank", "L"},
                                               {r.link.has_value(), "--link", "L"}})
      if (auto e = require(given, option, std::string("synthesize shaper needs ") + option + " " + shape)) return e;
    if (*r.timeRatio == 1.0)
      return usage("--time-ratio",
                   "--time-ratio must be greater than 1 for a crank-shaper (got 1: the pivots "
                   "would be infinitely far apart)");
    return std::nullopt;
  case SynthesisProblem::Function: return checkFunction(r);
  case SynthesisProblem::Motion: return checkMotion(r);
  case SynthesisProblem::Path:
    if (r.targets.size() < 4 || r.targets.size() > 10)
      return usage("--target",
                   "synthesize path needs --target X,Y 4 to 10 times (got " + std::to_string(r.targets.size()) + ")");
    if (!r.timingDeg.empty() && r.timingDeg.size() != r.targets.size())
      return usage("--timing", "--timing needs one crank angle per target (" + std::to_string(r.targets.size()) +
                                   "; got " + std::to_string(r.timingDeg.size()) + ")");
    if (r.timingFromFrame && r.timingDeg.empty())
      return usage("--timing-from", "--timing-from goes with --timing DEG,DEG,...");
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace linkwright::cli
