#pragma once
// `dxf` as one request for every front end: the links of a linkage drawn at one input
// (kinematics/analysis/link_drawing.h), that input the one asked for or where the design
// starts (its grid's first input, or its motion law's start). linkwright-cli dxf and Python's
// Linkage.dxf fill it alike and write the drawing through the same writer (io/dxf_export.h).

#include "kinematics/analysis/link_drawing.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/model/request_field.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// What a drawing is asked for.
struct DrawingRequest {
  /// The input drawn at: degrees for a crank, the length unit for a linear driver; else where
  /// the design starts.
  std::optional<double> at;
  DrawingOptions options;             ///< hole diameter and plate width (length unit), else chosen
  FrontEnd frontEnd = FrontEnd::Cli;  ///< who asked: the spelling of at, hole and width in refusals
};

/// A drawing made, and the input it was made at.
struct DrawingRun {
  LinkDrawing drawing;
  double at = 0.0;     ///< in the input's display unit (degrees, or the length unit)
  std::string atText;  ///< "crank angle 30°", "input 12.5 mm"
};

/// The drawing the request asks for of `mechanism` on `grid` (its source's; `source` names it
/// in messages). Errors: an input outside the driver's domain (InvalidValue), a pose that cannot
/// be assembled there (NotAssemblable), the drawing's own (InvalidValue, its field as spelled).
Result<DrawingRun> runDrawing(const Mechanism& mechanism, const SweepGrid& grid, const std::string& source,
                              const DrawingRequest& request);

}  // namespace linkwright::kinematics
