#pragma once
// What `synthesize` prints, whatever the problem: the candidates (each a SynthesisCandidate from
// kinematics/synthesis/ with its link lengths), which is best and why, and figures of the chosen
// one. solveSynthesis runs the core for a request; writeReportText and writeReportJson print it.

#include "app/cli/synthesize_options.h"

#include "kinematics/synthesis/candidate.h"
#include "kinematics/synthesis/path_generation.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::cli {

/// One figure of a candidate, printed for the chosen one: numbers or a word.
struct SynthesisDetail {
  enum class Kind { Length, AngleDeg, Plain, Text };
  std::string key;    ///< JSON member, snake_case with its unit ("extended_crank_angle_deg")
  std::string label;  ///< text label ("extended limit crank angle")
  Kind kind = Kind::Plain;
  std::vector<double> values;  ///< lengths in the length unit, angles in degrees
  std::string text;            ///< Kind::Text only
};

/// One candidate as listed.
struct CandidateRow {
  kinematics::SynthesisCandidate candidate;
  std::vector<std::pair<std::string, double>> dimensions;  ///< name and length (length unit), in table order
  std::optional<double> parameter;                         ///< swing: its place on the family, (−1, 1)
  std::vector<SynthesisDetail> details;
};

/// Everything found for one request.
struct SynthesisReport {
  SynthesisProblem problem = SynthesisProblem::Swing;
  std::string summary;  ///< what was asked, one line ("rocker swing 60°, time ratio 1.3, rocker 50 mm")
  std::string lengthUnit;
  std::string errorName;     ///< "worst output error" or "" for an exact construction
  std::string errorUnit;     ///< "deg" or the length unit (with errorName)
  double errorFactor = 1.0;  ///< candidate.error × errorFactor is the error in errorUnit
  std::vector<CandidateRow> rows;
  std::size_t best = 0;  ///< 0-based
  std::string bestRule;  ///< why that one is best
  double minTransmissionDeg = 40.0;
  std::optional<double> maxLink;
  double maxLinkRatio = 10.0;
};

/// Runs the core for the request. Errors name the option that caused them ("--rod: …").
/// `progress` hears of a path search's starts as they finish.
kinematics::Result<SynthesisReport> solveSynthesis(const SynthesisRequest& request,
                                                   const kinematics::PathProgress& progress = {});

/// The candidates' table, their defects with the reasons, and the chosen one (0-based).
void writeReportText(const SynthesisReport& report, std::size_t chosen, std::ostream& out);

/// The same as one JSON object; `document` is the file the chosen one was written to, if any.
void writeReportJson(const SynthesisReport& report, std::size_t chosen, const std::optional<std::string>& document,
                     std::ostream& out);

}  // namespace linkwright::cli
