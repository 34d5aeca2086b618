#pragma once
// `linkwright-cli synthesize PROBLEM …`: the options of each synthesis problem, parsed into a
// plain request. Numbers are read with std::from_chars ('.' is the decimal point whatever the
// locale); angles stay in degrees as typed and are converted by the command, at the edge. Every
// error names the option, the value and the accepted range.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::cli {

using kinematics::SynthesisProblem;

using kinematics::problemName;

/// The most --starts a path search takes from the command line, where it holds the shell and
/// only a terminal sees its progress: 2000 starts of ten targets without timing, the slowest
/// search, took 6.6 s of CPU on the development machine (3.3 ms each; six targets 0.6 ms). The
/// designer's Synthesis panel, where a search can be cancelled, takes up to 100000.
inline constexpr long long kMaxCliPathStarts = 2000;

/// A coupler pose as typed: X,Y in the length unit, the coupler's angle in degrees CCW from +x.
struct PoseOption {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double angleDeg = 0.0;
  bool operator==(const PoseOption&) const = default;
};

/// Everything `synthesize` was asked. Lengths in the length unit, angles in degrees.
struct SynthesisRequest {
  SynthesisProblem problem = SynthesisProblem::Swing;
  // Common: output, bounds and the candidate to write.
  std::string lengthUnit = "mm";
  double minTransmissionDeg = 40.0;  ///< [0, 90]
  std::optional<double> maxLink;     ///< positive; none: no bound
  double maxLinkRatio = 10.0;        ///< longest / shortest link, > 1
  bool json = false;
  std::optional<long long> choose;  ///< 1-based index in the printed list; none: the best
  std::optional<std::string> outputFile;
  // swing, slider, shaper
  std::optional<double> swingDeg;     ///< (0, 180)
  std::optional<double> timeRatio;    ///< [1, 100]
  std::optional<double> rocker;       ///< swing: the rocker's length
  std::optional<double> frame;        ///< swing: the frame's length; function: the frame (default 100)
  long long count = 11;               ///< swing: crank-rockers listed from the family, [1, 1000]
  std::optional<double> stroke;       ///< slider, shaper
  std::optional<double> rod;          ///< slider
  std::optional<double> offset;       ///< slider, any sign
  std::optional<double> crank;        ///< shaper
  std::optional<double> link;         ///< shaper
  std::optional<double> guideHeight;  ///< shaper
  // function
  std::string function;  ///< a name of kinematics::namedFunctions()
  std::optional<double> x0, x1;
  std::optional<double> inputStartDeg, inputSpanDeg, outputStartDeg, outputSpanDeg;
  std::optional<long long> points;  ///< Chebyshev points, [3, 1000]
  std::vector<double> at;           ///< the user's precision points
  // motion
  std::vector<PoseOption> poses;
  std::vector<Eigen::Vector2d> circlePoints;  ///< where the moving pivots are at pose 1 (world frame)
  std::vector<double> centres;                ///< two poses: each centre point along its bisector
  bool fullTurn = false;                      ///< a motor turns the crank round (Grashof crank required)
  // path
  std::vector<Eigen::Vector2d> targets;
  std::vector<double> timingDeg;  ///< crank angle at each target; empty: no timing
  bool timingFromFrame = false;   ///< --timing-from frame: from the frame line, else from a free start
  std::optional<long long> starts;
  std::optional<long long> seed;
};

/// The request's targets and bounds as a document keeps them (design/synthesis_targets.h):
/// its problem's section filled from the options, the others left at their defaults.
kinematics::SynthesisTargets targetsOf(const SynthesisRequest& request);

/// Error unless the request has what its problem needs (the options it cannot do without, no
/// two that exclude each other, the right counts of poses, circle points and targets, a range
/// where the named function is defined). Run by parseSynthesisArguments.
std::optional<kinematics::Error> checkSynthesisRequest(const SynthesisRequest& request);

/// Parses the arguments after "synthesize" (the problem first). Errors name the option.
kinematics::Result<SynthesisRequest> parseSynthesisArguments(const std::vector<std::string>& args);

}  // namespace linkwright::cli
