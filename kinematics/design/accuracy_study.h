#pragma once
// `accuracy` as one request for every front end: the speed-accuracy trade of reading peaks off
// a sampled cycle, measured on the seeds' linkages (analysis/sampling_accuracy.h) with the time
// each choice costs: peaks read off N samples, off frame differences, and refined between
// samples (Linkwright's), each against a refined 7200-sample reference; and every RRR joint
// solved by Newton at six tolerances against the closed form. linkwright-cli accuracy and
// Python's linkwright.accuracy run it alike; kinematics/io/accuracy_csv.h writes its rows.

#include "kinematics/analysis/sampling_accuracy.h"
#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// What the study is asked for: one example, or the four of the seeds (nullopt).
struct AccuracyRequest {
  std::optional<std::string> example;
  FrontEnd frontEnd = FrontEnd::Cli;  ///< who asked: the spelling of the field in refusals
};

/// The examples measured when none is named: a four-bar, a slider-crank, a shaper, a six-bar.
std::vector<std::string> defaultAccuracyExamples();

/// One row: a method at a grid, its median time and its errors against `reference`.
struct AccuracyRow {
  std::string example;
  std::string method;  ///< "samples", "frames", "refined", "closed-form", "newton-1e-06", …
  std::size_t samples = 0;
  double microseconds = 0.0;          ///< median wall time of five runs (varies run to run)
  PeakError error;                    ///< relative errors of the peaks; angle in rad
  std::string reference = "refined";  ///< what the errors are measured against ("-": none)
};

/// The study's rows, example by example. Errors: an example that does not exist or cannot be
/// measured, named as the front end spells "example". `control` is told of each example done
/// and may cancel between them.
Result<std::vector<AccuracyRow>> measureAccuracy(const AccuracyRequest& request, const RunControl& control = {});

}  // namespace linkwright::kinematics
