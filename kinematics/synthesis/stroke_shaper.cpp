#include "kinematics/synthesis/stroke_shaper.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/synthesis/defects.h"
#include "kinematics/synthesis/message_text.h"
#include "kinematics/synthesis/time_ratio.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

}  // namespace

Result<ShaperSynthesis> synthesiseShaper(const ShaperTarget& t, const DefectBounds& bounds) {
  if (auto e = checkLength(t.stroke, "stroke")) return *e;
  if (auto e = checkTimeRatio(t.timeRatio)) return *e;
  if (t.timeRatio == 1.0)
    return invalid("timeRatio",
                   "timeRatio must be greater than 1 for a crank-shaper (got 1): its pivots would be "
                   "infinitely far apart");
  if (auto e = checkLength(t.crank, "crank")) return *e;
  if (auto e = checkLength(t.link, "link")) return *e;
  if (t.guideHeight)
    if (auto e = checkCoordinate(*t.guideHeight, "guideHeight")) return *e;
  const double half = timeRatioAngle(t.timeRatio) / 2.0;
  const double most = t.stroke / (2.0 * (1.0 + std::sin(half)));
  if (!(t.crank < most))
    return invalid("crank",
                   "crank must be shorter than " + formatShort(most) +
                       " for this stroke and time ratio, or the lever would not reach past the crank pin (got " +
                       formatNumber(t.crank) + ")");
  ShaperGeometry g;
  g.crank = t.crank;
  const double d = t.crank / std::sin(half);
  g.rockerPivot = Eigen::Vector2d(0.0, -d);
  g.rocker = t.stroke / (2.0 * std::sin(half));
  g.link = t.link;
  // The tip's arc runs between heights −d + R·cos(α/2) (the limits) and −d + R (the middle).
  const double low = -d + g.rocker * std::cos(half), high = -d + g.rocker;
  g.guideHeight = t.guideHeight.value_or(0.5 * (low + high));
  const double reach = std::max(std::abs(g.guideHeight - low), std::abs(g.guideHeight - high));
  if (!(t.link > reach))
    return invalid("link", "link must be longer than " + formatShort(reach) +
                               " to reach the guide from every point of the lever tip's arc (got " +
                               formatNumber(t.link) + ")");
  auto m = makeShaper(g, Branch::Open, t.lengthUnit);
  if (!m) return m.error();
  Design design;
  design.kind = "shaper";
  design.mechanism = std::move(*m);
  // The link tilts most from the guide where the tip is furthest from the guide's height.
  const double mu = kPi / 2.0 - std::asin(reach / t.link);
  std::vector<Defect> defects;
  if (auto defect = transmissionDefect(mu, bounds)) defects.push_back(*defect);
  if (auto defect = linkLengthDefect({g.crank, g.rocker, g.link}, {"crank", "lever", "link"}, bounds))
    defects.push_back(*defect);
  return ShaperSynthesis{g, {std::move(design), 0.0, std::nullopt, mu, std::move(defects)}};
}

}  // namespace linkwright::kinematics
