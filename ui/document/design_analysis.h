#pragma once
// What the panels, the canvas and the animator know about the current design beyond its
// pose: mobility for any linkage; the Grashof class, transmission range and rocker limits for
// a four-bar; time ratio and stroke for a quick return; and the crank angles at which the
// linkage assembles (exact for a four-bar, the sweep's assembled samples otherwise). Every
// number comes from a core call; this file only picks which calls apply.

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/grashof.h"
#include "kinematics/analysis/limit_positions.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/analysis/quick_return.h"
#include "kinematics/analysis/transmission.h"
#include "kinematics/design/mechanism_design.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <vector>

namespace linkwright::ui {

struct DesignAnalysis {
  kinematics::MobilityReport mobility;
  /// Where the crank can be: the animator turns or rocks within it, the document clamps to it.
  kinematics::InputRange inputRange;
  /// Runs of the design's grid at which the linkage cannot be assembled (rad), as exported.
  std::vector<kinematics::AngleRange> notAssembled;
  std::optional<kinematics::GrashofReport> grashof;              ///< four-bars only
  std::optional<kinematics::TransmissionRange> transmission;     ///< four-bars only
  kinematics::LimitReport limits;                                ///< four-bars only (else empty)
  std::optional<kinematics::QuickReturnReport> quickReturn;      ///< shapers and Whitworths
};

/// Analyses `design`, whose mechanism is `mechanism` and whose sweep over its grid is `sweep`
/// (positions suffice).
DesignAnalysis analyseDesign(const kinematics::Design& design, const kinematics::Mechanism& mechanism,
                             const kinematics::SweepResult& sweep);

/// The input ranges over which `sweep` assembled, one per run of assembled samples (a lock
/// between two samples, SweepResult::lockedBetween, ends a run); a full
/// turn when every sample of a grid spanning 360° or more assembled.
kinematics::InputRange assembledRange(const kinematics::SweepResult& sweep);

/// A quick return's dimensions read back from its points, if `mechanism` still has the shape
/// makeShaper builds (O2, O4, crank B, slotted link D, ram R on a horizontal ground guide).
std::optional<kinematics::ShaperGeometry> shaperGeometryOf(const kinematics::Mechanism& mechanism,
                                                           kinematics::Branch* ramBranch = nullptr);

} // namespace linkwright::ui
