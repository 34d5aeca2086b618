#pragma once
// Four-bar function generators (Freudenstein 1955; as in Norton, Uicker–Pennock–Shigley and
// Wilson & Sadler): the rocker's angle follows y = f(x) as the crank's follows x. Both are
// linear maps:
//   θ2 = inputStart + inputSpan·(x − x0)/(x1 − x0),   θ4 = outputStart + outputSpan·(y − y0)/(y1 − y0),
// with y0 = f(x0), y1 = f(x1), angles frame-relative (fourbar.h). At the precision points x_j
// (Chebyshev spacing x_j = (x0+x1)/2 − (x1−x0)/2·cos((2j−1)π/2n) by default, or the user's) the
// pairs (θ2, θ4) go into Freudenstein's equation (freudenstein.h): three are met exactly, more
// in least squares. The structural error, the built linkage's output less the one wanted, is
// then taken over the whole range by solving the linkage with the pose solver on the branch of
// the first precision position, and its peak is located by golden section between samples.
//
// A crank or rocker that Freudenstein's K gives a negative length is built pointing the other
// way: the crank with phase π (so the design's input is still θ2), the output read as the
// rocker's angle less π (FunctionSynthesis::outputOffset).

#include "kinematics/synthesis/candidate.h"
#include "kinematics/synthesis/freudenstein.h"

#include <functional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// The function and the ranges it is mapped to.
struct FunctionTarget {
  std::function<double(double)> f;  ///< y = f(x), finite on [x0, x1]
  double x0 = 0.0;                  ///< start of the x range
  double x1 = 1.0;                  ///< end of the x range (> x0)
  double inputStart = 0.0;          ///< θ2 at x0 (rad, frame-relative)
  double inputSpan = 1.0;           ///< θ2 at x1 less θ2 at x0 (rad, nonzero, |span| < 2π)
  double outputStart = 0.0;         ///< θ4 at x0 (rad)
  double outputSpan = 1.0;          ///< θ4 at x1 less θ4 at x0 (rad, nonzero, |span| < 2π)
  double frame = 1.0;               ///< frame length d (length unit)
  std::string lengthUnit = "mm";
};

/// How to choose the precision points and sample the error.
struct FunctionOptions {
  std::vector<double> points;  ///< the precision x values, increasing; empty: `count` Chebyshev points
  std::size_t count = 3;       ///< Chebyshev points when `points` is empty (≥ 3)
  std::size_t samples = 201;   ///< error samples over [x0, x1] (≥ 2)
};

/// The structural error over the range.
struct StructuralError {
  std::vector<double> x;             ///< sample x values, including x0 and x1
  std::vector<double> outputError;   ///< rad: output angle less the wanted one, at each x
  std::vector<double> notAssembled;  ///< x values where the linkage cannot be assembled
  double maxAbs = 0.0;               ///< rad, the largest |error|, refined between samples
  double maxAt = 0.0;                ///< x where it occurs
  double maxAbsY = 0.0;              ///< the same in units of y: maxAbs·|y1 − y0|/|outputSpan|
};

struct FunctionSynthesis {
  std::vector<double> points;              ///< the precision x values used
  std::vector<AnglePair> precisionAngles;  ///< their (θ2, θ4)
  FreudensteinCoefficients k;
  FreudensteinLinkage linkage;
  Branch branch = Branch::Open;  ///< the assembly branch of the first precision position
  double outputOffset = 0.0;     ///< π if the rocker points the other way, else 0 (rad)
  StructuralError error;
  /// design: the four-bar, graded over the input range; error: error.maxAbs (rad);
  /// minTransmission over the input range.
  SynthesisCandidate candidate;
};

/// The function generator for a saved target (design/synthesis_targets.h): its function by
/// name (named_function.h; an unknown name or a range where it is undefined is an Error naming
/// "function", "x0" or "x1"), its precision points or Chebyshev count.
Result<FunctionSynthesis> synthesiseFunction(const FunctionSpec& spec, const std::string& lengthUnit,
                                             const DefectBounds& bounds = {});

/// n Chebyshev points on [x0, x1], increasing.
std::vector<double> chebyshevSpacing(double x0, double x1, std::size_t n);

/// The function generator for the target; Error naming the field ("function", "x1",
/// "inputSpan", "points[1]", "frame", …) for a bad target or a degenerate solution.
Result<FunctionSynthesis> synthesiseFunction(const FunctionTarget& target, const FunctionOptions& options = {},
                                             const DefectBounds& bounds = {});

}  // namespace linkwright::kinematics
