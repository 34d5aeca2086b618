#pragma once
// What a user designs and saves: a linkage (any Mechanism: a four-bar, a slider-crank, a
// shaper, a six-bar, anything built from dyads or free points), how its crank is driven and
// the angle grid it is analysed on, and its masses and loads. The GUI edits one of these, the
// document file stores one and the CLI resolves its options to one, so all three mean the same
// linkage. What a design *is* (a four-bar with a Grashof class, a quick return) is read from
// its mechanism's structure (model/recognise.h), never from how it was built or stored.

#include "kinematics/design/examples.h"
#include "kinematics/design/synthesis_targets.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

struct Design {
  std::string kind = "linkage";  ///< a label shown to the user: "four-bar", "slider-crank", "watt-ii", …
  Mechanism mechanism;
  // The input grid, in the input's display unit (driver.h): a crank's in degrees and rad/s, a
  // path's or actuator's in the length unit and per second.
  double omega = 1.0;         ///< the driver's rate: a crank's rad/s (CCW positive)
  double alpha = 0.0;         ///< the driver's acceleration: a crank's rad/s²
  double fromDeg = 0.0;       ///< analysis grid start: a crank's degrees
  double toDeg = 360.0;       ///< analysis grid end: a crank's degrees
  std::size_t samples = 721;  ///< grid points from fromDeg to toDeg inclusive (≥ 2)
  LinkageDynamics dynamics;   ///< masses and loads for forces, by link and point name; empty: none
  /// A time base: the crank follows a motion law, analysed at `samples` instants from its
  /// fromTime to its toTime; omega, alpha, fromDeg and toDeg are then unused.
  std::optional<TimeBase> time;
  /// What the linkage was synthesised for (synthesis_targets.h): the targets and bounds the
  /// designer's synthesis panel shows again; none when it was never asked.
  std::optional<SynthesisTargets> synthesis;
  bool operator==(const Design&) const = default;
};

/// Error naming the first invalid field: a four-bar's lengths ("lengths.coupler"), the
/// mechanism's ("points[3].firstLength"), the
/// driver's and grid's ("omega", "alpha", "fromDeg", "toDeg", "samples") or the dynamics'
/// ("dynamics.links[0].mass").
std::optional<Error> checkDesign(const Design& design);

/// The driver and grid rules every design shares: ω, α and the grid's ends within the input
/// domain of the driver's kind, toDeg > fromDeg, 2 ≤ samples ≤ 10 000 000. Fields "omega",
/// "alpha", "fromDeg", "toDeg", "samples".
std::optional<Error> checkDriveAndGrid(double omega, double alpha, double fromDeg, double toDeg, std::size_t samples,
                                       InputKind kind = InputKind::Angle);

/// checkDynamics with "dynamics." before the field and the message.
std::optional<Error> checkDesignDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics);

/// Grid points every 0.5° from fromDeg to toDeg inclusive: how examples become designs.
std::size_t samplesEveryHalfDegree(double fromDeg, double toDeg);

/// The design's analysis grid: its angles at its crank speed, or its time base.
SweepSpec designSweepSpec(const Design& design);

/// One full crank turn from the grid's start at the design's ω (1 rad/s if it is 0), with the
/// grid's samples, at least 361 and at most kMaxTurnSamples: what a turn's machine figures
/// (machine_duty.h) are computed over for a design.
SweepSpec designTurn(const Design& design);

/// A four-bar design (makeFourBar's points O2, O4, B, C and P, links crank, coupler,
/// rocker) at ω = 1 rad/s over a full turn every 0.5°. Fails, naming the field, as makeFourBar.
Result<Design> fourBarDesign(const FourBarLengths& lengths, Branch branch = Branch::Open,
                             const std::string& lengthUnit = "mm",
                             std::optional<CouplerPointSpec> couplerPoint = std::nullopt);

/// A built-in example as a design, sampled every 0.5° over its range.
Design designFromExample(const Example& example);

/// The built-in example named `name` as a design, if there is one.
std::optional<Design> designForExample(const std::string& name);

}  // namespace linkwright::kinematics
