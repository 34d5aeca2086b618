#pragma once
// What a designer asks of a linkage before it exists: the targets of each synthesis problem
// (kinematics/synthesis/) and the bounds every candidate is checked against. Plain data, so a
// Design can keep them (design.h: the document saves them, the designer shows them again) and
// the synthesis below reads them; the problems themselves live in kinematics/synthesis/.
// Angles in radians, lengths in the design's length unit.

#include "kinematics/model/units.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// The bounds a candidate is checked against. Length bounds are in the design's length unit.
struct DefectBounds {
  double minTransmission = degToRad(40.0);  ///< rad; a worst transmission angle below it is a defect
  std::optional<double> maxLinkLength;      ///< a link longer than this is a defect; none: no bound
  /// Longest / shortest link above this is a defect; none: no bound. The default, 10, is the
  /// usual rule of thumb; families whose transmission keeps improving as the linkage grows
  /// without end (the in-line crank-rocker) pick their best within it.
  std::optional<double> maxLinkRatio = 10.0;
  bool operator==(const DefectBounds&) const = default;
};

/// Which length the user fixes; the others follow from the family point.
enum class SwingScale {
  Rocker,  ///< `length` is the rocker's
  Frame,   ///< `length` is the frame's (the linkage is scaled to it)
};

/// What the rocker must do.
struct SwingTarget {
  double swing = 0.0;      ///< ψ, rad, in (0, π)
  double timeRatio = 1.0;  ///< Q, slow stroke / quick stroke, in [1, kMaxTimeRatio]
  double length = 1.0;     ///< the fixed length (length unit)
  SwingScale scale = SwingScale::Rocker;
  std::string lengthUnit = "mm";
  bool operator==(const SwingTarget&) const = default;
};

/// Which dimension the user fixes.
enum class SliderChoice {
  Rod,     ///< `value` is the rod length b
  Offset,  ///< `value` is the offset e (any sign: a negative one mirrors the linkage)
};

/// What the slider must do.
struct StrokeTarget {
  double stroke = 0.0;     ///< H, the slider's travel (length unit, > 0)
  double timeRatio = 1.0;  ///< Q, slow stroke / quick stroke, in [1, kMaxTimeRatio]
  SliderChoice choice = SliderChoice::Rod;
  double value = 0.0;  ///< the rod length or the offset (length unit)
  std::string lengthUnit = "mm";
  bool operator==(const StrokeTarget&) const = default;
};

/// What the ram must do, and the free dimensions.
struct ShaperTarget {
  double stroke = 0.0;                ///< H, the ram's travel (length unit)
  double timeRatio = 1.5;             ///< Q, in (1, kMaxTimeRatio]
  double crank = 0.0;                 ///< r, the crank (length unit), below H / (2 (1 + sin(α/2)))
  double link = 0.0;                  ///< D to the ram (length unit)
  std::optional<double> guideHeight;  ///< y of the ram's guide; none: mid-height of the tip's arc
  std::string lengthUnit = "mm";
  bool operator==(const ShaperTarget&) const = default;
};

/// Where the coupler must be: its point P (length unit) and its angle φ (rad, CCW from +x).
struct CouplerPose {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double angle = 0.0;
  bool operator==(const CouplerPose&) const = default;
};

/// The free choices: the two circle points, where they are at pose 1 (length unit).
struct CirclePoints {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  ///< the crank's moving pivot
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  ///< the rocker's moving pivot
  bool operator==(const CirclePoints&) const = default;
};

/// What the prescribed crank angles are measured from.
enum class TimingReference {
  Start,  ///< θ_i = θ0 + τ_i with θ0 free: only the differences between the τ_i matter
  Frame,  ///< θ_i = β + τ_i: τ_i measured from the frame line O2→O4 (the literature's usual form)
};

/// The path to follow.
struct PathTarget {
  /// The targets (length unit), in the order the coupler point must meet them; 4 to 10,
  /// distinct. Collinear targets are allowed: a straight-line path is a real task.
  std::vector<Eigen::Vector2d> points;
  /// Crank angle at each target (rad), the same count as points; empty: no timing.
  std::vector<double> timing;
  TimingReference timingReference = TimingReference::Start;
  bool needsFullRotation = false;  ///< a motor turns the crank round (a Grashof crank is then required)
  std::string lengthUnit = "mm";
  bool operator==(const PathTarget&) const = default;
};

/// A function generator's target by name (synthesis/named_function.h), so it can be saved:
/// y = f(x) over [x0, x1], mapped linearly to the crank's and the rocker's angles.
struct FunctionSpec {
  std::string function = "log10";  ///< a name of namedFunctions()
  double x0 = 1.0;
  double x1 = 10.0;
  double inputStart = 0.0;     ///< θ2 at x0 (rad, frame-relative)
  double inputSpan = 1.0;      ///< θ2 at x1 less θ2 at x0 (rad)
  double outputStart = 0.0;    ///< θ4 at x0 (rad)
  double outputSpan = 1.0;     ///< θ4 at x1 less θ4 at x0 (rad)
  double frame = 100.0;        ///< frame length (length unit)
  std::vector<double> points;  ///< the precision x values; empty: `count` Chebyshev points
  std::size_t count = 3;
  bool operator==(const FunctionSpec&) const = default;
};

/// The coupler poses a motion generator must pass through and its free choices.
struct MotionTargets {
  std::vector<CouplerPose> poses;  ///< two or three
  CirclePoints circlePoints;
  double centreA = 0.0;  ///< two poses: where each centre point lies on its bisector (length unit)
  double centreB = 0.0;
  bool needsFullRotation = false;
  bool operator==(const MotionTargets&) const = default;
};

/// How hard a path search looks (synthesis/path_generation.h's PathOptions, what is saved).
struct PathSearch {
  int starts = 400;
  std::uint32_t seed = 19;
  bool operator==(const PathSearch&) const = default;
};

enum class SynthesisProblem { Swing, Slider, Shaper, Function, Motion, Path };

/// "swing", "slider", "shaper", "function", "motion", "path": the CLI's and the document's name.
inline const char* problemName(SynthesisProblem problem) {
  switch (problem) {
  case SynthesisProblem::Swing: return "swing";
  case SynthesisProblem::Slider: return "slider";
  case SynthesisProblem::Shaper: return "shaper";
  case SynthesisProblem::Function: return "function";
  case SynthesisProblem::Motion: return "motion";
  case SynthesisProblem::Path: return "path";
  }
  return "swing";
}

/// Every problem's targets, the one being worked on, and the bounds: what a document keeps.
struct SynthesisTargets {
  SynthesisProblem problem = SynthesisProblem::Swing;
  SwingTarget swing;
  StrokeTarget slider;
  ShaperTarget shaper;
  FunctionSpec function;
  MotionTargets motion;
  PathTarget path;
  PathSearch pathSearch;
  DefectBounds bounds;
  bool operator==(const SynthesisTargets&) const = default;
};

}  // namespace linkwright::kinematics
