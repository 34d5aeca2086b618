#pragma once
// What a four-bar and its two cognates (cognates.h) do over the original's cycle, read from one
// sweep of the original: each one's crank angle over every stretch the original moves through
// without a break, and the original coupler's ω3/ω2, which cognate 1's crank turns at. The
// cognates' joints at every sample come from the construction (cognateJoints), so no cognate
// is swept: its motion in step with the original is that construction's. The worst transmission
// angle over a stretch is then exact (transmission.h): a crank's stretch is the interval
// between its least and greatest angle, as its motion is continuous; where the crank turns back,
// its extreme is the exact edge of its assembly range.

#include "kinematics/explore/cognates.h"
#include "kinematics/model/recognise.h"
#include "kinematics/solve/sweep.h"

#include <array>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// A crank's angle from its frame line (rad, continuous) over one stretch of the cycle: its
/// first, least and greatest value, and whether the crank turns back at the least or the
/// greatest while the original's crank goes on (at a sample inside the stretch, on an angle
/// grid). A crank that stops while the linkage moves is at a toggle: its coupler and rocker
/// fold, so there it is at the edge of the angles it can be assembled at.
struct CrankRun {
  double start = 0.0;
  double least = 0.0;
  double greatest = 0.0;
  bool turnsBackAtLeast = false;
  bool turnsBackAtGreatest = false;
};

struct CognateCycle {
  /// Per four-bar (the original, cognate 1, cognate 2): its crank's runs, one per stretch of
  /// consecutive assembled samples with no lock between them, in sweep order. The first
  /// starts at sample 0 when that sample is assembled.
  std::array<std::vector<CrankRun>, 3> runs;
  /// The original coupler's ω3 over its crank's ω2 (dimensionless), least and greatest, at the
  /// samples where both are defined and ω2 ≠ 0; none if there is no such sample.
  std::optional<double> couplerSpeedRatioMin;
  std::optional<double> couplerSpeedRatioMax;
};

/// The cycle of `swept` (a sweep of the four-bar `fourBar` with positions and velocities) with
/// `traced` its coupler point.
CognateCycle cognateCycle(const SweepResult& swept, const FourBarStructure& fourBar, PointId traced);

/// The worst min(μ, π − μ) of `lengths`' transmission angle over the crank's `runs` (rad);
/// none if there are no runs or one of them cannot be followed exactly. Where a crank turns
/// back, the sampled extreme is moved to the edge of its assembly range (assembly_range.h)
/// that the samples bracket, so a toggle's μ of 0 is found, not the nearest sample's.
std::optional<double> worstTransmissionOverRuns(const FourBarLengths& lengths, const std::vector<CrankRun>& runs);

}  // namespace linkwright::kinematics
