#pragma once
// The one place a design's derived state comes from. Every edit in the designer, every file it
// opens and the CLI's verdict on a linkage pass through deriveDesign: it checks the candidate,
// recognises its structure, judges whether it assembles anywhere and analyses it, or refuses it
// with the one sentence for each reason. The designer's document holds what it returns and
// nothing else, so no message or figure outlives the design it was made for.

#include "kinematics/design/design.h"
#include "kinematics/design/design_analysis.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>

namespace linkwright::kinematics {

/// What follows from an accepted design besides its pose and plots.
struct DerivedDesign {
  std::optional<FourBarStructure> fourBar;  ///< its four-bar, read from its structure
  DesignAnalysis analysis;
};

/// Whether deriving `mechanism` reads a sweep of its design's grid (positions only): every
/// linkage but a four-bar whose crank turns fully (its closed forms say all).
bool needsGridSweep(const Mechanism& mechanism);

/// The design's grid as deriveDesign reads it: designSweepSpec's angles, positions only.
SolveRequest gridSweepRequest(const NewtonSettings& newton = {});

/// Accepts `candidate` or says why not: checkDesign's error naming the field, or
/// assemblesNowhere's (ErrorCode::NotAssemblable, field "design"). `gridSweep` is the
/// candidate's grid swept with gridSweepRequest when needsGridSweep, else ignored (an empty
/// result will do).
Result<DerivedDesign> deriveDesign(const Design& candidate, const SweepResult& gridSweep);

/// As above for a mechanism already checked (the CLI's, resolved from its options).
Result<DerivedDesign> deriveDesign(const Mechanism& mechanism, const SweepResult& gridSweep);

/// As above, sweeping the grid itself when it is needed.
Result<DerivedDesign> deriveDesign(const Design& candidate, const NewtonSettings& newton = {});

}  // namespace linkwright::kinematics
