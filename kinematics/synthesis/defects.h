#pragma once
// The defect check every four-bar candidate goes through, exactly (no sampling):
// - not Grashof: the task needs a motor to turn the crank fully and the crank cannot (grashof.h);
// - branch (circuit): the required positions are drawn on different assembly branches, or lie
//   in different ranges of crank angle (assembly_range.h), so no continuous motion joins them;
// - order: turning the crank one way, the positions come in another order than required;
// - transmission: the worst transmission angle over the working range is below the bound. μ
//   depends on the crank angle θ only through the diagonal BD, monotonic in cos θ, so over a
//   range its extremes lie at the range's ends or at θ = 0, π inside it (transmission.h);
// - link length: a link longer than the bound, or longest / shortest above the bound.
// Angles here are crank angles measured from the frame line O2→O4 (rad), as in fourbar.h.

#include "kinematics/analysis/grashof.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/synthesis/candidate.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// A crank range from `from` to `to` (rad, frame-relative); `to` may be less than `from`
/// (the crank turning clockwise). Its length is |to − from| ≤ 2π.
struct CrankSpan {
  double from = 0.0;
  double to = 0.0;
  bool operator==(const CrankSpan&) const = default;
};

/// What a four-bar must do, for the defect check.
struct FourBarTask {
  FourBarLengths lengths;
  /// Crank angles (rad, frame-relative) of the required positions, in the order required.
  std::vector<double> crankAngles;
  /// The assembly branch each required position is drawn on (four-bar convention, fourbar.h);
  /// the same size as crankAngles.
  std::vector<Branch> branches;
  /// A motor turns the crank round and round (crank-rockers for a swing, say).
  bool needsFullRotation = false;
  /// The crank's working range, for the transmission angle; none: every assemblable angle.
  std::optional<CrankSpan> workingRange;
};

/// The check's findings.
struct FourBarCheck {
  GrashofReport grashof;
  double minTransmission = 0.0;  ///< rad, worst min(μ, π − μ) over the working range; 0 if it never assembles
  std::vector<Defect> defects;
};

/// Checks `task` (valid lengths) against `bounds`.
FourBarCheck checkFourBar(const FourBarTask& task, const DefectBounds& bounds);

/// The worst min(μ, π − μ) over the crank range (rad), or nullopt if some angle in the range
/// cannot be assembled.
std::optional<double> worstTransmissionOver(const FourBarLengths& lengths, const CrankSpan& span);

/// The worst min(μ, π − μ) over every assemblable crank angle (rad), or nullopt if the linkage
/// never assembles.
std::optional<double> worstTransmission(const FourBarLengths& lengths);

/// The link-length defect (longest link or longest/shortest ratio above the bounds), if any.
/// `lengths` and `names` are the linkage's links and their names, the same size.
std::optional<Defect> linkLengthDefect(const std::vector<double>& lengths, const std::vector<std::string>& names,
                                       const DefectBounds& bounds);

/// `angle` (rad) brought into [0, 2π).
double wrapPositive(double angle);

/// The crank's motion from the first of `angles` (rad, at least two) to the last, the way that
/// passes the second (with two, the shorter way).
CrankSpan crankSpanThrough(const std::vector<double>& angles);

/// The transmission defect if `minTransmission` (rad) is below the bound.
std::optional<Defect> transmissionDefect(double minTransmission, const DefectBounds& bounds);

}  // namespace linkwright::kinematics
