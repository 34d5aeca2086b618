#pragma once
// Shaking-force balance by counterweights (Norton, Design of Machinery, ch. 12; Berkof and
// Lowen, "A new method for completely force balancing simple linkages", 1969). The shaking
// force is −Σ m a_G over the moving masses, so it vanishes when their common centre of mass
// stands still. Each body's masses are summed to its mass m and first moment M (kg·length unit,
// a complex number in the body's frame: along and across the line from its pivot or first joint
// to its other joint); a counterweight adds to M, at a distance r from the pivot, the mass
// |ΔM|/r in the direction of ΔM.
//
//   Four-bar (Berkof–Lowen, linearly independent vectors). With the crank O2→B (l2, angle θ2),
//   the coupler B→C (l3, θ3), the rocker O4→C (l4, θ4) and the loop closure
//   l3 e^{iθ3} = O2O4 + l4 e^{iθ4} − l2 e^{iθ2}, the total first moment is
//     e^{iθ2} (M2 + m3 l2 − M3 l2/l3) + e^{iθ4} (M4 + M3 l4/l3) + const,
//   stationary for every θ2 when both brackets vanish: counterweights on the crank and the
//   rocker make M2 = M3 l2/l3 − m3 l2 and M4 = −M3 l4/l3, for the coupler's masses as given.
//   The balance is complete: the shaking force is zero to round-off at every pose and speed.
//   Slider-crank (the textbook crank counterweight). The rod's masses are lumped at its pins,
//   m3 (1 − b/l3) at B and m3 b/l3 at C (b the rod's centre of mass along B→C; exact for a rod
//   whose centre lies on that line); B's share and the crank's own moment rotate, C's share and
//   the slider reciprocate (m_r). A crank counterweight that balances the rotating masses and the
//   fraction k of m_r leaves the shaking force −m_r (a_C + k r ω² e^{iθ2}) at constant ω: the
//   primary force along the guide falls to (1 − k) of itself, and k of it turns across the guide.
//
// Each counterweight is a point mass (no inertia of its own) on the body's first link, at the
// link's own length from the pivot unless asked otherwise. A link holds one set of mass
// properties, so the counterweight joins them: the link's mass grows by it, its centre of mass
// moves to the pair's and its inertia gains the parallel-axis terms (a link without masses
// takes the counterweight's). The design stays an ordinary, editable one.

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

struct BalanceOptions {
  /// Slider-crank: the fraction k of the reciprocating mass the crank's counterweight balances,
  /// in [0, 1]; 0.5 by default (between a horizontal and a vertical primary force).
  double reciprocatingFraction = 0.5;
  /// Each counterweight's distance from its pivot as a multiple of its link's length, in
  /// [0.1, 10]; 1 by default.
  double radius = 1.0;
};

/// A counterweight the balance added: a point mass on `link`.
struct Counterweight {
  std::string link;       ///< the link it is on, by name
  double mass = 0.0;      ///< kg
  LinkFramePoint centre;  ///< in the link's frame, length unit
};

struct ForceBalance {
  std::string method;  ///< what was balanced and how, one line for people
  std::vector<Counterweight> counterweights;
  LinkageDynamics balanced;  ///< the given dynamics with the counterweights joined to their links' masses
};

/// The counterweights that balance the shaking force of a four-bar (completely) or a
/// slider-crank (its rotating masses and a fraction of the reciprocating ones). Errors name the
/// field: "linkage" for any other mechanism or one without a link on the body to carry a
/// counterweight, "dynamics" when it has no masses, "fraction" or "radius" out of range, or
/// the dynamics' own (checkDynamics).
Result<ForceBalance> balanceShakingForce(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                         const BalanceOptions& options = {});

}  // namespace linkwright::kinematics
