#pragma once
// The four-bar linkage built on the general model: ground pivots O2 (crank) at the origin and
// O4 (rocker) at (frame, 0), crank tip B, and one RRR dyad giving the coupler–rocker joint C.
// Link names and angles follow the thesis seed (000): crank O2→B (θ2), coupler B→C (θ3),
// rocker O4→C (θ4, the thesis's "θ4 (outer)").

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <optional>

namespace linkwright::kinematics {

/// Four-bar link lengths, all in one length unit.
struct FourBarLengths {
  double frame = 0.0;    ///< O2 to O4, along +x
  double crank = 0.0;    ///< O2 to B, the driven input link
  double coupler = 0.0;  ///< B to C
  double rocker = 0.0;   ///< O4 to C, the output link
  bool operator==(const FourBarLengths&) const = default;
};

/// A point fixed on the coupler, in the coupler's frame: `along` B→C, `across` 90° CCW from it.
struct CouplerPointSpec {
  double along = 0.0;
  double across = 0.0;
  bool operator==(const CouplerPointSpec&) const = default;
};

/// Fixed ids of the mechanism makeFourBar builds.
namespace fourbar {
inline constexpr PointId kO2{0};
inline constexpr PointId kO4{1};
inline constexpr PointId kB{2};
inline constexpr PointId kC{3};
inline constexpr PointId kCouplerPoint{4};  ///< present only when a coupler point is given
inline constexpr LinkId kCrank{0};
inline constexpr LinkId kCoupler{1};
inline constexpr LinkId kRocker{2};
}  // namespace fourbar

/// Error naming the first non-positive, NaN or infinite length ("frame", "crank", ...).
std::optional<Error> checkFourBarLengths(const FourBarLengths& lengths);

/// Builds the four-bar; points O2, O4, B, C (and P for the coupler point), links crank,
/// coupler, rocker. Fails with the field named if a length is invalid.
Result<Mechanism> makeFourBar(const FourBarLengths& lengths, Branch branch, const std::string& lengthUnit = "mm",
                              std::optional<CouplerPointSpec> couplerPoint = std::nullopt);

}  // namespace linkwright::kinematics
