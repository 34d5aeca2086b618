#pragma once
// The commands behind linkwright-cli: analyze (CSV table), extremes (refined extreme values),
// classify (Grashof class, transmission angle, limit positions, assemblable range; four-bars),
// arm (a two-link arm's joints along a straight tip path), centres (instant centres and
// mechanical advantage at given crank angles), polygon (velocity and acceleration polygons at
// given crank angles), inversions (a four-bar's or slider-crank's inversions), dxf (the links
// as a DXF drawing), report (the lab-report PDF), compare (another tool's table against the
// exact solution), synthesize (linkages from the motion wanted: kinematics/synthesis/),
// cognates (a four-bar's Roberts–Chebyshev cognates), tolerance (sensitivities and a Monte-Carlo
// tolerance study), optimise (a better linkage by one measure), atlas (a classified grid of
// coupler curves) and examples (the built-ins).

#include "app/cli/arguments.h"
#include "app/cli/exit_codes.h"

#include "kinematics/design/design.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <iosfwd>

namespace linkwright::cli {

ExitCode runAnalyze(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runClassify(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runExamples(std::ostream& out);
ExitCode runExtremes(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runArm(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runCentres(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runPolygon(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runInversions(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runAccuracy(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runDxf(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runReport(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runCompare(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runSynthesize(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runMachine(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runBalance(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runCognates(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runTolerance(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runOptimise(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runAtlas(const AtlasOptions& options, std::ostream& out, std::ostream& err);

/// What an example or a document brings besides the linkage: the driver's speed and the input
/// grid (kinematics/design/sweep_grid.h, shared with the Python module).
using GridDefaults = kinematics::SweepGrid;

/// The linkage an invocation describes (--fourbar lengths, an --example or a document),
/// built, with --branch and --coupler-point applied where it is a four-bar. What it is (a
/// four-bar with exact ranges, a quick return) is read from its structure (asFourBar, …).
struct ResolvedMechanism {
  kinematics::Mechanism mechanism;
  GridDefaults defaults;
  kinematics::LinkageDynamics dynamics;  ///< the document's or example's masses and loads (may be empty)
  std::string source;                    ///< "the example NAME", "FILE", "--fourbar": for messages
  std::string kind;                      ///< the example's or document's label ("slider-crank"); "" for --fourbar
  std::string description;               ///< the example's description; "" otherwise
};
kinematics::Result<ResolvedMechanism> resolveMechanism(const Invocation& invocation);

/// The document or the example an invocation names, whole, for the commands that write a new
/// design from it.
kinematics::Result<kinematics::Design> resolveDesign(const Invocation& invocation);

/// The sweep the speed and range options ask for, with `defaults` for what they leave out.
kinematics::Result<kinematics::SweepSpec> sweepSpecFor(const Invocation& invocation, const GridDefaults& defaults);

/// --rpm, --omega, --alpha, --from, --to and --step against the input's domain
/// (kinematics/model/validate.h, driver.h), each refusal naming the option as typed, its value
/// and the range in that option's unit; nullopt when all fit.
std::optional<kinematics::Error> checkDriveOptions(const Invocation& invocation, kinematics::InputKind kind);

/// --at against the input's domain (an instant within ±1e6 s on a time base, else the input in
/// degrees or the length unit): out of it is bad input (exit 2), not a pose that cannot be
/// assembled (exit 3), for every command that takes it.
std::optional<kinematics::Error> checkAtOption(const Invocation& invocation, const GridDefaults& defaults);

/// The grid fields as the options spell them (--rpm, --omega, --alpha, --from, …).
const kinematics::GridFieldNames& gridOptionNames();

/// `request` with --law and its options added (the core's grid rule makes them a time base:
/// kinematics/design/sweep_grid.h), the --law-table file read; errors name --law-table.
kinematics::Result<kinematics::SweepGridRequest> lawRequest(const Invocation& invocation, const GridDefaults& defaults,
                                                            kinematics::SweepGridRequest request);

/// One note on `err` per lock between two samples of `sweep` (SweepResult::lockedBetween):
/// the linkage cannot turn through, and points jump where it is assembled afresh.
void noteLocks(const kinematics::Mechanism& mechanism, const std::vector<kinematics::AngleRange>& lockedBetween,
               std::ostream& err);

}  // namespace linkwright::cli
