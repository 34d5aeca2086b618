#pragma once
// What the Python module holds for one linkage, and the sweep it tabulates, in plain C++ (no
// pybind11 here, so this part reads as the core does). A Linkage is a mechanism with the grid
// `linkwright-cli analyze` would use for the same source: an example's own speed and step, a
// document's grid, or the CLI's defaults for a four-bar given by its lengths (ω = 1 rad/s,
// 0° to 360° every 1°). The sweep is solved in windows and written through the core's
// SweepCsvWriter, so the module's CSV is the CLI's byte for byte, and its columns are the
// CSV's: the same rows (samples that assembled), the same names, the values the cells hold.

#include "kinematics/design/design.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::python {

struct Linkage {
  kinematics::Mechanism mechanism;
  kinematics::SweepGrid grid;            ///< the source's speed and grid (the CLI's, kinematics/design/sweep_grid.h)
  kinematics::LinkageDynamics dynamics;  ///< masses and loads, if the source gives them
  std::string kind;                      ///< "four-bar", "slider-crank", …; "" when not known
  std::string source;                    ///< "the example NAME", a path, "four_bar()": for messages
  /// The grid of the source as a design (linkwright-cli's resolveDesign: an example sampled
  /// every 0.5° over its range, a document's own grid; fourBarDesign's for four_bar()): what
  /// cognates, balance and optimise start from, as the CLI's do.
  struct DesignGrid {
    double omega = 1.0;         ///< rad/s
    double alpha = 0.0;         ///< rad/s²
    double fromDeg = 0.0;       ///< degrees (a linear driver: its length unit)
    double toDeg = 360.0;       ///< likewise
    std::size_t samples = 721;  ///< both ends counted
  } designGrid;
};

/// The linkage as the design the CLI reads from the same source (Linkage::designGrid).
kinematics::Design linkageDesign(const Linkage& linkage);

/// The built-in example `name`; an unknown name is an error listing the names.
kinematics::Result<Linkage> exampleLinkage(const std::string& name);

/// A four-bar from its lengths (one length unit), on `branch` ("open" or "crossed"), with a
/// coupler point P if given; errors name the length as typed ("coupler").
kinematics::Result<Linkage> fourBarLinkage(const kinematics::FourBarLengths& lengths, const std::string& unit,
                                           const std::string& branch,
                                           std::optional<kinematics::CouplerPointSpec> couplerPoint);

/// A design (a document's, a synthesis's) with its own grid, as linkwright-cli reads a document;
/// `source` names it in messages.
Linkage designLinkage(const kinematics::Design& design, std::string source);

/// The linkage as text, for pickle: its mechanism, masses and time base as a document (the
/// document writer keeps every double to the bit) and its grid's numbers; and back.
std::string linkageState(const Linkage& linkage);
kinematics::Result<Linkage> linkageFromState(const std::string& state);

/// A Linkwright document, read through the core's bounded reader; errors name the file.
kinematics::Result<Linkage> loadLinkage(const std::string& path);

/// What a sweep call asks for; anything left out is the linkage's grid.
struct SweepOptions {
  std::optional<double> startDeg;  ///< grid start, degrees (a linear driver: its length unit)
  std::optional<double> stopDeg;   ///< grid end, likewise; included when the step lands on it
  std::optional<long long> samples;
  std::optional<double> omega;  ///< rad/s (a linear driver: length unit per s)
  std::optional<double> alpha;  ///< rad/s² (a linear driver: length unit per s²)
  // A motion law in time instead of the grid, as linkwright-cli analyze --law: startDeg is
  // where it starts, omega its speed, samples or stepTimeS its instants.
  std::optional<std::string> law;  ///< "constant", "ramp", "cycloidal", "345", "table"
  std::optional<double> rampTimeS;
  std::optional<double> riseDeg;  ///< degrees (a linear driver: its length unit)
  std::optional<double> durationS;
  std::optional<std::string> lawTable;  ///< a CSV of time_s and the input (law "table")
  std::optional<double> fromTimeS;
  std::optional<double> toTimeS;
  std::optional<double> stepTimeS;
};

/// The sweep the options ask for: the core's grid rule (kinematics/design/sweep_grid.h), as
/// linkwright-cli's, a law's table read through the core's bounded reader, with the Python
/// parameter names in every refusal ("start_deg", "samples", "ramp_time_s", …).
kinematics::Result<kinematics::SweepSpec> sweepSpecFor(const Linkage& linkage, const SweepOptions& options);

/// A swept table: the CSV text, and the same table as columns.
struct SweepTable {
  std::vector<std::string> names;           ///< CSV header, in order
  std::vector<std::vector<double>> values;  ///< per column, per written row; 0 where `defined` is false
  std::vector<std::vector<bool>> defined;   ///< per column, per row: false where the CSV cell is empty
  std::string csv;                          ///< the CSV text (only when asked for)
  kinematics::SweepSummary summary;         ///< what the sweep found besides its rows
};

/// What a sweep call delivers.
struct TableRequest {
  bool csv = false;      ///< the CSV text
  bool columns = false;  ///< the columns
  bool forces = false;   ///< the force columns too (analyze --forces): needs the linkage's dynamics
};

/// Solves the sweep (and its forces, if asked for); errors name "forces" when the linkage has
/// no masses or a window's forces cannot be solved.
kinematics::Result<SweepTable> sweepTable(const Linkage& linkage, const kinematics::SweepSpec& spec,
                                          const TableRequest& request);

}  // namespace linkwright::python
