#pragma once
// Parses linkwright-cli's command line into a plain Invocation. Numbers are read with
// std::from_chars, so '.' is the decimal point whatever the locale. Every error names the
// option and the reason.

#include "kinematics/model/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::cli {

enum class Command { Help, Version, Examples, Analyze, Classify, Extremes };

/// Everything the user asked for. Angles in degrees and speeds as typed: converted to SI by
/// the commands, at the edge.
struct Invocation {
  Command command = Command::Help;
  std::string helpTopic;  ///< "analyze" or "classify" for command help, else empty
  std::optional<kinematics::FourBarLengths> fourBar;
  std::optional<std::string> example;
  std::string lengthUnit = "mm";
  std::optional<double> rpm;
  std::optional<double> omega;  ///< rad/s
  std::optional<double> alpha;  ///< rad/s²
  std::optional<double> fromDeg;
  std::optional<double> toDeg;
  std::optional<double> stepDeg;
  std::optional<long long> samples;
  std::optional<kinematics::Branch> branch;
  std::optional<kinematics::CouplerPointSpec> couplerPoint;
  std::optional<std::string> outputFile;
  bool json = false;
  bool tableFormat = false;  ///< analyze --format table: aligned text instead of CSV
};

/// Parses the arguments after the program name.
kinematics::Result<Invocation> parseArguments(const std::vector<std::string>& args);

} // namespace linkwright::cli
