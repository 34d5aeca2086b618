#pragma once
// What the panels, the canvas and the animator know about a linkage beyond its pose:
// mobility for any linkage; the Grashof class, transmission range and rocker limits when it
// is a four-bar; time ratio and stroke when it is a quick return; and the crank angles at
// which it assembles (exact for a four-bar, the grid sweep's assembled samples otherwise).
// Which of these apply is read from the mechanism's structure (model/recognise.h), not from
// how the design was stored.

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/grashof.h"
#include "kinematics/analysis/limit_positions.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/analysis/quick_return.h"
#include "kinematics/analysis/transmission.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

struct DesignAnalysis {
  MobilityReport mobility;
  /// Where the crank can be (input angles): the animator turns or rocks within it, the
  /// document clamps to it.
  InputRange inputRange;
  /// Runs of the design's grid at which the linkage cannot be assembled (rad), as exported.
  std::vector<AngleRange> notAssembled;
  std::optional<GrashofReport> grashof;           ///< four-bars only
  std::optional<TransmissionRange> transmission;  ///< four-bars only; crank angles are input angles in [0, 2π)
  LimitReport limits;                             ///< four-bars only (else empty); input angles in [0, 2π)
  std::optional<QuickReturnReport> quickReturn;   ///< shapers and Whitworths
};

/// Analyses `mechanism`, whose sweep over its design's grid is `gridSweep` (positions
/// suffice; for a four-bar only its notAssembled is read, so an empty result will do).
DesignAnalysis analyseDesign(const Mechanism& mechanism, const SweepResult& gridSweep);

/// Why `mechanism` cannot be shown or analysed at all, or nullopt: it assembles at no input. A
/// four-bar is judged by its closed-form crank range (`gridSweep` is not read), any other
/// linkage by its sweep over its input (positions suffice): no sample assembled. The one
/// sentence the designer's refusal and the CLI's exit 3 give (ErrorCode::NotAssemblable,
/// field "design").
std::optional<Error> assemblesNowhere(const Mechanism& mechanism, const SweepResult& gridSweep);

/// The input ranges over which `sweep` assembled, one per run of assembled samples (a lock
/// between two samples, SweepResult::lockedBetween, ends a run); a full turn when every
/// sample of a crank's grid spanning 360° or more assembled (a linear input never turns).
InputRange assembledRange(const SweepResult& sweep, InputKind input = InputKind::Angle);

}  // namespace linkwright::kinematics
