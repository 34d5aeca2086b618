#pragma once
// The crank-shaper quick-return mechanism on the general model: crank pivot O2 at the origin,
// crank tip B, a slotted rocker pivoted at O4 whose slot slides through a block pinned at B
// (an RPR dyad; its tip D is `rocker` from O4), and a link D→R driving the ram R along a
// horizontal guide at height `guideHeight` (an RRP dyad). Seed 003 (Miranda et al.) analyses
// one; it omits the frame, and the geometry that reproduces its extremes is O4 200 mm below
// and 40 mm to the side of O2, guide 220 mm above O2.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// Shaper dimensions, in one length unit.
struct ShaperGeometry {
  double crank = 0.0;                                     ///< O2 to B
  double rocker = 0.0;                                    ///< O4 to D, the slotted link
  double link = 0.0;                                      ///< D to the ram R
  Eigen::Vector2d rockerPivot = Eigen::Vector2d::Zero();  ///< O4, relative to O2
  double guideHeight = 0.0;                               ///< y of the ram's horizontal guide
  bool operator==(const ShaperGeometry&) const = default;
};

namespace shaper {
inline constexpr PointId kO2{0};
inline constexpr PointId kO4{1};
inline constexpr PointId kB{2};
inline constexpr PointId kD{3};
inline constexpr PointId kRam{4};
inline constexpr LinkId kCrank{0};
inline constexpr LinkId kRocker{1};
inline constexpr LinkId kLink{2};
}  // namespace shaper

/// Error naming the field if a length is not positive and finite or a position not finite,
/// or if the rocker pivot lies on the crank circle (the pin would pass through it). A pivot
/// outside the circle gives the crank-shaper; inside, the Whitworth form.
std::optional<Error> checkShaper(const ShaperGeometry& geometry);

/// Builds the shaper; Branch::Open puts the ram on the +x side of D.
Result<Mechanism> makeShaper(const ShaperGeometry& geometry, Branch branch = Branch::Open,
                             const std::string& lengthUnit = "mm");

}  // namespace linkwright::kinematics
