#pragma once
// Random linkages of every kind for the soak (soak_main.cpp): four-bars of every Grashof class
// and exact change points, slider-cranks with and without offsets, crank-shapers and
// Whitworths, the four dyad six-bars, perturbed Newton six-bars, linkages driven other than by
// a crank (two-link arms with their tips on segments, polylines and arcs that may leave the
// workspace, piston-driven slider-crank, cylinder-driven rockers), and near-degenerate ones
// (collinear pivots, zero offsets, lengths at the input domain's ends). Deterministic for a
// seed: numbers come from mt19937's raw output, which the standard fixes (its distributions
// are not fixed, so a library change would draw other linkages).

#include "kinematics/model/mechanism.h"

#include <optional>
#include <random>
#include <string>

namespace linkwright::test {

enum class LinkageKind { FourBar, SliderCrank, Shaper, SixBar, Newton, Driven };
inline constexpr LinkageKind kAllKinds[] = {LinkageKind::FourBar, LinkageKind::SliderCrank, LinkageKind::Shaper,
                                            LinkageKind::SixBar,  LinkageKind::Newton,      LinkageKind::Driven};

std::string kindName(LinkageKind kind);

/// A drawn linkage: its mechanism, or the builder's refusal (a draw outside the input domain),
/// and the input range to sweep: a full crank turn, or a linear driver's travel (length unit).
struct DrawnLinkage {
  std::string description;  ///< the dimensions, to reproduce a finding
  std::optional<kinematics::Mechanism> mechanism;
  std::string refusal;  ///< the builder's message when it refused
  double inputFrom = 0.0;
  double inputTo = 2.0 * 3.141592653589793;
  double inputScale = 1.0;  ///< the input's size: the drawn driver speed is multiplied by it
};

DrawnLinkage drawLinkage(LinkageKind kind, std::mt19937& rng);

/// Uniform in (0, 1) from one raw mt19937 output.
double unit(std::mt19937& rng);

}  // namespace linkwright::test
