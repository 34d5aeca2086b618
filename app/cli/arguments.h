#pragma once
// Parses linkwright-cli's command line into a plain Invocation. Numbers are read with
// std::from_chars, so '.' is the decimal point whatever the locale. Every error names the
// option and the reason.

#include "app/cli/atlas_options.h"
#include "app/cli/synthesize_options.h"

#include "kinematics/compare/table_comparison.h"
#include "kinematics/design/balance_request.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::cli {

enum class Command {
  Help,
  Version,
  Examples,
  Analyze,
  Classify,
  Extremes,
  Arm,
  Centres,
  Polygon,
  Inversions,
  Accuracy,
  Synthesize,
  Dxf,
  Report,
  Compare,
  Machine,
  Balance,
  Cognates,
  Tolerance,
  Optimise,
  Atlas
};

/// compare --offset: auto (fitted), none, or a value in degrees.
struct CompareOffsetOption {
  kinematics::compare::OffsetMode mode = kinematics::compare::OffsetMode::Auto;
  double degrees = 0.0;
};

/// compare --tolerance PCT[,ABS]: percent of each column's span, and an absolute part in each
/// column's unit (default: its rounding).
struct CompareToleranceOption {
  double percent = 0.25;
  std::optional<double> absolute;
};

/// The fields of the request `command` is, if it is one (machine), else empty.
const std::vector<kinematics::RequestField>& requestFieldsOf(Command command);

/// Everything the user asked for. Angles in degrees and speeds as typed: converted to SI by
/// the commands, at the edge.
struct Invocation {
  Command command = Command::Help;
  std::string helpTopic;  ///< a command's name for its help, else empty
  std::optional<kinematics::FourBarLengths> fourBar;
  std::optional<std::string> example;
  std::optional<std::string> documentPath;  ///< a Linkwright document (FILE.json) to analyse
  std::string lengthUnit = "mm";
  std::optional<double> rpm;
  std::optional<double> omega;  ///< rad/s
  std::optional<double> alpha;  ///< rad/s²
  std::optional<double> fromDeg;
  std::optional<double> toDeg;
  std::optional<double> stepDeg;
  std::optional<long long> samples;
  // analyze on a time base: the crank follows a motion law (kinematics/solve/motion_law.h).
  std::optional<std::string> law;       ///< constant, ramp, cycloidal, 345 or table
  std::optional<double> rampTime;       ///< s, ramp
  std::optional<double> riseDeg;        ///< degrees, cycloidal and 345
  std::optional<double> duration;       ///< s, cycloidal and 345
  std::optional<std::string> lawTable;  ///< a CSV of time_s and the crank angle in degrees, table
  std::optional<double> fromTime;       ///< s
  std::optional<double> toTime;         ///< s
  std::optional<kinematics::Branch> branch;
  std::optional<kinematics::CouplerPointSpec> couplerPoint;
  std::optional<std::string> couplerPointName;  ///< cognates --coupler-point NAME: a point on the coupler
  std::optional<std::string> outputFile;
  bool json = false;
  bool tableFormat = false;  ///< --format table: aligned text instead of CSV (analyze, arm)
  bool forces = false;       ///< analyze --forces: add joint forces, driving torque and shaking (needs masses)
  // arm: a two-link arm whose tip follows a straight line (lengths in the length unit).
  std::optional<std::pair<double, double>> arm;  ///< upper, forearm; positive, finite
  std::optional<Eigen::Vector2d> fromPoint;      ///< finite
  std::optional<Eigen::Vector2d> toPoint;        ///< finite
  std::optional<double> speed;                   ///< length unit / s; positive, finite
  std::optional<double> stepTime;                ///< s; positive, finite
  std::optional<kinematics::Branch> elbow;       ///< up = Open, down = Crossed
  // centres, polygon: crank angles in degrees, finite, in the order given (--at is repeatable).
  std::vector<double> atDeg;
  std::optional<std::string> svgFile;         ///< accuracy --svg: where to draw the error plot
  std::optional<SynthesisRequest> synthesis;  ///< synthesize: the problem and its options
  std::optional<AtlasOptions> atlas;          ///< atlas: the grid, the filter and what to write
  // dxf: the drawing's sizes (length unit; positive, finite), empty for the defaults.
  std::optional<double> holeDiameter;
  std::optional<double> plateWidth;
  std::optional<std::string> paper;   ///< report --paper: a4 or letter (checked by the command)
  std::optional<std::string> rates;   ///< report --rates: rad or deg (checked by the command)
  std::optional<std::string> angles;  ///< report --angles: deg or rad (checked by the command)
  // compare: another tool's table (the bare argument after the document, or the only one).
  std::optional<std::string> compareTable;
  std::optional<std::string> compareMap;  ///< --map text (kinematics/compare/column_mapping.h)
  std::optional<CompareOffsetOption> compareOffset;
  std::optional<CompareToleranceOption> compareTolerance;
  // A capability defined as a request (kinematics/model/request_field.h; machine): its options
  // are its fields' (--gear-ratio for gear_ratio), read as numbers by key; the core checks them.
  kinematics::RequestValues requestValues;
  // balance (kinematics/dynamics/force_balance.h); the core checks the ranges.
  std::optional<double> reciprocatingFraction;  ///< --fraction, slider-cranks
  std::optional<double> counterweightRadius;    ///< --radius, in link lengths
  std::optional<std::string> springEnds;        ///< --spring LINK:POINT,POINT (balance by a spring)
  std::optional<std::string> springSearchLink;  ///< --spring-search LINK (the spring's ends searched)
  // tolerance (kinematics/tune/tolerance_monte_carlo.h); the core checks the ranges.
  std::optional<double> tolerance;  ///< --tolerance, ± on every dimension, length unit
  /// --tolerance-of "NAME=T,…": dimensions with a ± of their own (tolerance).
  std::vector<std::pair<std::string, double>> toleranceOf;
  std::optional<long long> monteCarloSamples;  ///< --mc-samples
  std::optional<unsigned long long> seed;      ///< --seed
  // optimise (kinematics/tune/optimise_linkage.h); the core checks the ranges.
  std::optional<std::string> objective;       ///< --objective KIND[:ARGUMENT], parsed by the command
  std::optional<std::string> objectivePoint;  ///< --point, the path objective's point (default P)
  std::optional<std::string> pathMeasure;     ///< --path-measure worst|rms
  std::optional<double> lengthRangePercent;   ///< --length-range, ± percent of each length, in (0, 95]
  std::optional<std::string> fixPivots;       ///< --fix-pivots NAME,NAME|all|none
  std::optional<long long> evaluations;       ///< --evaluations
  std::optional<long long> starts;            ///< --starts
};

/// balance's options as the core's request (kinematics/design/balance_request.h).
kinematics::BalanceRequest balanceRequestOf(const Invocation& invocation);

/// Parses the arguments after the program name.
kinematics::Result<Invocation> parseArguments(const std::vector<std::string>& args);

}  // namespace linkwright::cli
