#pragma once
// The slider-crank built on the general model: crank pivot O2 at the origin, crank tip B, and
// one RRP dyad giving the slider (piston) pin C on a straight guide parallel to +x at height
// `offset`. Links: crank O2→B, rod B→C. With `reversed` the guide points along −x, so the
// slider works on the other side of the crank. Seed 003 (Miranda et al.) analyses the LS3
// engine this way.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// Slider-crank dimensions, in one length unit.
struct SliderCrankGeometry {
  double crank = 0.0;     ///< O2 to B (half the stroke when offset = 0)
  double rod = 0.0;       ///< B to C, the connecting rod
  double offset = 0.0;    ///< the guide's distance from O2 (y of the guide line), may be 0 or negative
  bool reversed = false;  ///< guide direction −x instead of +x
  bool operator==(const SliderCrankGeometry&) const = default;
};

/// Fixed ids of the mechanism makeSliderCrank builds.
namespace slidercrank {
inline constexpr PointId kO2{0};
inline constexpr PointId kB{1};
inline constexpr PointId kC{2};
inline constexpr LinkId kCrank{0};
inline constexpr LinkId kRod{1};
}  // namespace slidercrank

/// Error naming "crank", "rod" or "offset" if a value is invalid.
std::optional<Error> checkSliderCrank(const SliderCrankGeometry& geometry);

/// Builds the slider-crank; Branch::Open puts the slider at the far end of the guide from the
/// crank pivot (the usual engine), Crossed at the near end.
Result<Mechanism> makeSliderCrank(const SliderCrankGeometry& geometry, Branch branch = Branch::Open,
                                  const std::string& lengthUnit = "mm");

}  // namespace linkwright::kinematics
