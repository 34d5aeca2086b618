#pragma once
// The input grid a sweep runs over: what a front end's options ask for (a speed, a range, a
// step or a sample count), with what the linkage's source brings for the rest (an example's
// speed and step, a document's grid, the defaults for a four-bar given by its lengths). One
// rule for linkwright-cli and the Python module, so they agree by construction
// (docs/style.md). Each front end passes its own spelling of the fields ("--from",
// "start_deg") for the messages; an error's field is the neutral key (gridFieldKey).

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// What an example or a document brings besides the linkage: the driver's speed and the input
/// grid, in the input's display unit (degrees for a crank, the length unit for a linear driver).
struct SweepGrid {
  double omega = 1.0;  ///< rad/s
  double alpha = 0.0;  ///< rad/s²
  double fromDeg = 0.0;
  double toDeg = 360.0;
  double stepDeg = 1.0;
  std::optional<TimeBase> time;  ///< a document's time base: its crank's motion law
  long long timeSamples = 0;     ///< the instants of that time base
  /// What fromDeg, toDeg, stepDeg and a law's start are in: degrees for a crank, the length
  /// unit for a path or actuator driver.
  InputKind input = InputKind::Angle;
  std::string lengthUnit = "mm";  ///< the linkage's: a linear driver's table names it
  /// The grid value `value` (degrees or length) as the driver's coordinate (rad or length).
  double toInput(double value) const;
};

/// An example's own speed and grid.
SweepGrid sweepGridOf(const Example& example);
/// A document's grid: its samples become the step that reproduces them.
SweepGrid sweepGridOf(const Design& design);

/// What a turn's duty takes from the grid (machine_request.h): the speed, the grid's start, and
/// whether the crank follows a motion law instead.
MachineDefaults machineDefaultsOf(const SweepGrid& grid);

/// The fields of a grid request.
enum class GridField {
  Rpm,
  Omega,
  Alpha,
  Start,
  Stop,
  Step,
  Samples,
  Law,
  RampTime,
  Rise,
  Duration,
  LawTable,
  FromTime,
  ToTime,
  StepTime
};

/// The neutral key an error's field holds: "rpm", "omega", "alpha", "start", "stop", "step",
/// "samples", "law", "rampTime", "rise", "duration", "lawTable", "fromTime", "toTime", "stepTime".
const char* gridFieldKey(GridField field);

/// How a front end spells each field in its messages ("--from", "start_deg"); an empty name is
/// a field the front end does not offer (no rpm, no step, no law).
struct GridFieldNames {
  std::string rpm, omega, alpha, start, stop, step, samples, law;
  std::string rampTime, rise, duration, lawTable, fromTime, toTime, stepTime;
  const std::string& operator[](GridField field) const;
};

/// What the caller gives; anything left out is the source's grid (SweepGrid).
struct SweepGridRequest {
  std::optional<double> rpm;    ///< rev/min, instead of omega
  std::optional<double> omega;  ///< rad/s (a linear driver: length unit per s)
  std::optional<double> alpha;  ///< rad/s² (a linear driver: length unit per s²)
  std::optional<double> start;  ///< grid start, degrees (a linear driver: its length unit)
  std::optional<double> stop;   ///< grid end, likewise; included when the step lands on it
  std::optional<double> step;   ///< grid step, likewise
  std::optional<long long> samples;
  // A motion law in time instead of the grid (kinematics/solve/motion_law.h): `start` is where
  // it starts, omega (or rpm) its speed, `samples` or stepTime the instants.
  std::optional<std::string> law;  ///< "constant", "ramp", "cycloidal", "345" or "table"
  std::optional<double> rampTime;  ///< s: ramp
  std::optional<double> rise;      ///< degrees (a linear driver: its length unit): cycloidal, 345
  std::optional<double> duration;  ///< s: cycloidal, 345
  std::optional<TableLaw> table;   ///< table: q(t) read by the front end (io/law_table_csv.h)
  std::optional<double> fromTime;  ///< s: the first instant (default: the table's first, or 0)
  std::optional<double> toTime;    ///< s: the last (default: the rise's end, a ramp and a turn, a turn)
  std::optional<double> stepTime;  ///< s: between instants, instead of samples
};

/// The laws `law` may name, in the order messages list them.
inline constexpr const char* kMotionLawNames[] = {"constant", "ramp", "cycloidal", "345", "table"};
/// The instants of a law's time base when neither samples nor stepTime is given.
inline constexpr long long kDefaultLawSamples = 361;

/// The speed and range fields against the input's domain (kinematics/model/validate.h,
/// driver.h), each refusal naming the field as the front end spells it, its value and the range
/// in that field's unit; nullopt when all fit.
std::optional<Error> checkGridRequest(const SweepGridRequest& request, InputKind kind, const GridFieldNames& names);

/// A crank's state at `deg` degrees (what one pose is drawn at: polygon): ω from the request's
/// rpm or omega, else the source's; α from its alpha, else the source's. Each checked in its own
/// unit against the crank's domain, named as `names` and `atName` spell them ("--at", "at").
Result<DriverState> crankStateAt(double deg, const SweepGridRequest& request, const SweepGrid& defaults,
                                 const GridFieldNames& names, const std::string& atName);

/// The sweep the request asks for, with `defaults` for what it leaves out: with `law`, that law's
/// time base (lawGridSpec); on the source's own time base its instants; else the input grid from
/// start to stop (the last grid value not past stop) every step or at `samples` points.
Result<SweepSpec> sweepGridSpec(const SweepGridRequest& request, const SweepGrid& defaults,
                                const GridFieldNames& names);

/// The time base `request.law` asks for (law_grid.cpp): the law by name with its figures,
/// starting at `start` (else the source's grid start) at omega (rpm, else the source's speed),
/// from fromTime to toTime at `samples` or every stepTime. Refused: a law without its figures,
/// figures of another law, the angle grid's stop, step or alpha beside it, stepTime with
/// samples, an end before the start, too many instants.
Result<SweepSpec> lawGridSpec(const SweepGridRequest& request, const SweepGrid& defaults, const GridFieldNames& names);

}  // namespace linkwright::kinematics
