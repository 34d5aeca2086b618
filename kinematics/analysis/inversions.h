#pragma once
// Kinematic inversions (Norton §2.11, Uicker §1.8): the same chain with another link held
// fixed. The relative motions of the links do not change, the absolute ones do, so each
// inversion is a different mechanism: Grashof's rule gives its class from where the shortest
// link sits (Norton Table 2-4, after classifyGrashof):
//   S + L < P + Q  ground a link adjacent to the shortest  → crank-rocker (twice)
//                  ground the shortest                     → double-crank (drag link)
//                  ground the link opposite the shortest   → double-rocker (Grashof: the coupler turns fully)
//   S + L > P + Q  every inversion                         → triple-rocker (non-Grashof)
//   S + L = P + Q  every inversion                         → change point
// Each inversion is built as a four-bar whose frame is the grounded link and whose crank (the
// driven link) is adjacent to it: the one that turns fully when one does, else the shorter.
//
// The slider-crank (crank a, rod b, offset e) has four inversions (Norton Fig. 2-15):
//   ground the guide (frame) → slider-crank; the crank turns fully iff a + |e| ≤ b
//   ground the crank         → rotating guide: the rod turns about B; the old frame, a slotted
//                              guide through O2, turns fully iff a < b (Whitworth quick return),
//                              else rocks (crank-shaper); built as an RPR dyad (e = 0 only)
//   ground the rod           → oscillating cylinder: the crank turns about B, the block at C is
//                              a cylinder the old frame (a piston rod through O2) slides in; the
//                              cylinder rocks iff a < b; an RPR dyad about C (e = 0 only)
//   ground the slider        → fixed piston (pendulum or hand pump): the rod swings about C and
//                              O2 slides on a line parallel to the guide at −e: an RRP dyad;
//                              the rod turns fully iff b + |e| ≤ a
// An RPR slot passes through its pivot, so an offset guide (e ≠ 0) cannot be built for the
// second and third: they are named, with the reason, and have no mechanism.

#include "kinematics/analysis/grashof.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/result.h"
#include "kinematics/model/slider_crank.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkwright::kinematics {

/// The textbook's name of a Grashof class: "crank-rocker", "double-crank (drag link)",
/// "double-rocker (Grashof)", "change point", "triple-rocker (non-Grashof)".
std::string_view textbookName(GrashofClass category);

/// One inversion of a four-bar chain.
struct FourBarInversion {
  LinkRole grounded = LinkRole::Frame;  ///< the link of the original four-bar held fixed
  LinkRole driven = LinkRole::Crank;    ///< the original link that is the inversion's crank
  /// The inversion as a four-bar: frame = the grounded link, crank = the driven one, then
  /// coupler and rocker going on round the loop (length unit as the original).
  FourBarLengths lengths;
  GrashofReport grashof;  ///< classifyGrashof(lengths): category, which links turn fully
  std::string name;       ///< textbookName(grashof.category)
  Mechanism mechanism;    ///< makeFourBar(lengths, branch, unit): sweep it like any four-bar
  bool operator==(const FourBarInversion&) const = default;
};

/// The four inversions, grounding the original's frame, crank, coupler and rocker in turn.
/// Errors: a length that is not positive and finite (the field named as checkFourBarLengths).
Result<std::vector<FourBarInversion>> fourBarInversions(const FourBarLengths& lengths, Branch branch = Branch::Open,
                                                        const std::string& lengthUnit = "mm");

/// Which link of a slider-crank an inversion grounds.
enum class SliderCrankLink { Frame, Crank, Rod, Slider };

/// One inversion of a slider-crank chain.
struct SliderCrankInversion {
  SliderCrankLink grounded = SliderCrankLink::Frame;
  std::string name;    ///< "slider-crank", "Whitworth quick return (rotating guide)", …
  std::string driven;  ///< the original link the inversion drives: "crank" or "rod"
  /// The driven link turns fully relative to the new ground (from the closed forms above).
  bool driverTurnsFully = false;
  /// The output (guide, cylinder, slider) turns fully; false for the slider-crank's slider.
  bool outputTurnsFully = false;
  /// The inversion on the general model, driven by `driven`; empty when the model cannot
  /// express it (`note` says why).
  std::optional<Mechanism> mechanism;
  std::string note;
  bool operator==(const SliderCrankInversion&) const = default;
};

/// "frame (guide)", "crank", "rod", "slider".
std::string_view toString(SliderCrankLink link);

/// A recognised slider-crank's dimensions read back from its points (asSliderCrank): crank
/// |O2B|, rod, and the guide's signed distance from O2, the guide's direction taken as +x (so
/// `reversed` is false). nullopt when the crank turns about a moving pivot: not the textbook
/// slider-crank.
std::optional<SliderCrankGeometry> sliderCrankGeometry(const Mechanism& mechanism,
                                                       const SliderCrankStructure& structure);

/// The four inversions of `geometry` (its `reversed` flag mirrors the first only). Errors as
/// checkSliderCrank.
Result<std::vector<SliderCrankInversion>> sliderCrankInversions(const SliderCrankGeometry& geometry,
                                                                const std::string& lengthUnit = "mm");

/// A linkage's inversions, whichever chain it is: a four-bar's (fourBar set) or a
/// slider-crank's (sliderCrank set).
struct LinkageInversions {
  std::optional<FourBarLengths> fourBar;  ///< the four-bar's lengths, its inversions in fourBars
  std::vector<FourBarInversion> fourBars;
  std::optional<SliderCrankGeometry> sliderCrank;  ///< the slider-crank's, its inversions in sliderCranks
  std::vector<SliderCrankInversion> sliderCranks;
};

/// The inversions of `mechanism` as a four-bar (any points on its links) or else as a
/// slider-crank driven by its crank. Refused, naming `source` ("the example shaper") and its
/// `kind` ("" when not known), for any other linkage; errors of the inversions otherwise.
Result<LinkageInversions> linkageInversions(const Mechanism& mechanism, const std::string& source,
                                            const std::string& kind);

}  // namespace linkwright::kinematics
