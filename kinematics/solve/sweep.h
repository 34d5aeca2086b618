#pragma once
// A sweep solves a mechanism over a range of input angles at a given crank ω and α, or over a
// range of times with the crank following a motion law (motion_law.h), tracking
// each dyad's assembly branch continuously. Results are stored one column per quantity,
// allocated once before the loop. Link angles are unwrapped, so they are continuous (no jumps
// at ±180°).
//
// Branch tracking: away from toggle positions a dyad's branch cannot change, so each sample
// keeps the previous sample's branch. A dyad toggles only where the distance between its
// parents reaches an assembly limit; when a step cannot rule that out (the distance to the
// limit at both ends is small against how far the parents move), the step is halved
// recursively, down to 1e-7 rad; there the candidate nearest the linear extrapolation
// of the path is taken. This follows a change-point linkage smoothly through its singular
// position: a parallelogram stays a parallelogram, an antiparallelogram stays crossed.
//
// Speed: away from toggles the samples are solved kMaxBlock at a time (solveBlockInto), then
// checked one by one as above; the first sample whose step is not plainly safe, and every
// sample of a linkage with free points, is solved alone. The numbers are the same either way.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/motion_law.h"
#include "kinematics/solve/pose.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// A time base: the driver follows `law` (motion_law.h), sampled at evenly spaced instants
/// from `fromTime` to `toTime` inclusive (s).
struct TimeBase {
  MotionLaw law;
  double fromTime = 0.0;
  double toTime = 0.0;
  bool operator==(const TimeBase&) const = default;
};

/// The input range and state of a sweep, in one of two forms:
/// - an angle grid: `samples` evenly spaced inputs from `fromAngle` to `toAngle` (rad)
///   inclusive (one sample: `fromAngle` only), at each of which the crank has angular
///   velocity `omega` (rad/s) and acceleration `alpha` (rad/s²): a kinematic state table, as
///   the seeds' tables are;
/// - a time base (`time` set; the angles, ω and α above are then unused): `samples` instants,
///   at each of which the crank's angle, ω and α are the motion law's.
struct SweepSpec {
  double fromAngle = 0.0;
  double toAngle = 0.0;
  std::size_t samples = 1;
  double omega = 0.0;
  double alpha = 0.0;
  std::optional<TimeBase> time;
  bool operator==(const SweepSpec&) const = default;
};

/// A closed interval of input angles (rad).
struct AngleRange {
  double from = 0.0;
  double to = 0.0;
  bool operator==(const AngleRange&) const = default;
};

/// Everything a sweep computed. Outer index: point or link id; inner index: sample.
/// Quantities not requested have no columns (the outer vector is empty); points and links
/// outside request.only, and points that are not dyads for transmissionAngle, have empty ones. Rate columns (velocity, acceleration, ω,
/// α) hold 0 at samples that are not ok(): check the report before reading them. Position
/// columns are valid wherever assembled().
struct SweepResult {
  SolveRequest request;
  std::vector<double> time;        ///< s, on a time base (SweepSpec::time); else empty
  std::vector<double> inputAngle;  ///< rad
  std::vector<PoseReport> report;  ///< per sample: Ok, Singular or NotAssemblable
  std::vector<std::vector<Eigen::Vector2d>> position;
  std::vector<std::vector<Eigen::Vector2d>> velocity;
  std::vector<std::vector<Eigen::Vector2d>> acceleration;
  std::vector<std::vector<double>> linkAngle;          ///< rad, unwrapped over the sweep
  std::vector<std::vector<double>> linkOmega;          ///< rad/s
  std::vector<std::vector<double>> linkAlpha;          ///< rad/s²
  std::vector<std::vector<double>> transmissionAngle;  ///< rad, transmissionJoints only; others empty
  std::vector<AngleRange> notAssembled;                ///< runs of consecutive samples that failed
  std::vector<double> singularAngles;                  ///< samples where rates are undefined (toggle)
  /// Steps from one assembled sample to the next that the linkage cannot make: somewhere
  /// between them a dyad passes its assembly limit, so the crank cannot turn through (a lock
  /// too short to hold a sample). The later sample is assembled afresh on the mechanism's own
  /// branches, so points may jump across the step; it is not motion.
  std::vector<AngleRange> lockedBetween;
  std::optional<std::string> firstFailure;  ///< sentence describing the first failed sample

  std::size_t size() const { return inputAngle.size(); }
  bool ok(std::size_t sample) const { return report[sample].status == PoseStatus::Ok; }
  bool assembled(std::size_t sample) const { return report[sample].status != PoseStatus::NotAssemblable; }
  /// True if the linkage locks between `sample` and the next (lockedBetween holds that step).
  bool lockedAfter(std::size_t sample) const;
  /// Every column equal, to the last bit (a worker's sweep against the GUI thread's).
  bool operator==(const SweepResult&) const = default;
};

/// Error naming the field ("law.duration", "from time", …) for an invalid law, a non-finite
/// time, toTime < fromTime, a law that would turn the crank past ±1e6 degrees, or times outside
/// a table law's data.
std::optional<Error> checkTimeBase(const TimeBase& time, InputKind kind = InputKind::Angle);

/// Error naming the field if the spec has a non-finite angle, ω or α, or zero samples; or, on
/// a time base, an invalid law, a non-finite time, toTime < fromTime, or times outside a table
/// law's data.
/// The bounds are those of the driver's kind (driver.h's InputDomain).
std::optional<Error> checkSweepSpec(const SweepSpec& spec, InputKind kind = InputKind::Angle);

/// The input angle of sample `index` (rad).
double sweepAngle(const SweepSpec& spec, std::size_t index);

/// The instant of sample `index` on a time base (s); 0 without one.
double sweepTime(const SweepSpec& spec, std::size_t index);

/// The crank's angle, ω and α at sample `index`.
DriverState sweepDriver(const SweepSpec& spec, std::size_t index);

/// What a search between samples moves along: the input angle on an angle grid (rad), the
/// instant on a time base (s), at sample `index`.
double sweepParameter(const SweepSpec& spec, std::size_t index);

/// The driver's state at `parameter` (as sweepParameter's), between samples as well.
DriverState sweepDriverAt(const SweepSpec& spec, double parameter);

/// Copies sample j of a sweep into a prepared pose: positions, velocities and accelerations of
/// every point, angle, ω and α of every link. The sweep must hold all of them (the default
/// request, no selection); the pose's other entries are left as they were.
void copySampleToPose(const SweepResult& sweep, std::size_t sample, Pose& pose);

/// What a whole sweep found besides its columns, as SweepResult holds it: a sweep in windows
/// (sweepInWindows) gathers it over every window.
struct SweepSummary {
  std::size_t samples = 0;
  std::size_t assembledSamples = 0;
  std::vector<AngleRange> notAssembled;
  std::vector<double> singularAngles;
  std::vector<AngleRange> lockedBetween;
  std::optional<std::string> firstFailure;
  bool operator==(const SweepSummary&) const = default;
};

/// Samples a windowed sweep solves and hands on at a time (sweepInWindows, SweepWindows) for
/// every front end: a few megabytes of columns for a six-bar with forces, whatever the sample
/// count.
inline constexpr std::size_t kSweepWindow = 4096;

/// A window of a sweep: samples [first, first + part.size()) of it. `part`'s columns, reports
/// and input angles are those samples' (indices from 0); its notAssembled, singularAngles and
/// lockedBetween are the ones within the window, and its firstFailure the sweep's first if it
/// lies there. Returns false to stop the sweep.
using SweepWindowSink = std::function<bool(const SweepResult& part, std::size_t first)>;

/// The sweep delivered in windows of at most `window` samples, the same numbers as sweep(), in
/// memory that does not grow with the sample count: what a table of 10⁷ rows is written
/// from. Fails as sweep() does, before any window, or with ErrorCode::Cancelled when `sink`
/// returns false.
Result<SweepSummary> sweepInWindows(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                                    std::size_t window, const SweepWindowSink& sink);

/// A sweep read a window at a time, each window asked for in turn by its reader (the windows
/// sweepInWindows hands on, pulled rather than pushed): what two sweeps read side by side are
/// made of, a tolerance sample's windows against the nominal's. The same numbers as sweep(), in
/// the memory of one window; it keeps copies of what it was given.
class SweepWindows {
public:
  /// Fails as sweep() does, before any window.
  static Result<SweepWindows> start(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                                    std::size_t window);
  SweepWindows(SweepWindows&&) noexcept;
  SweepWindows& operator=(SweepWindows&&) noexcept;
  ~SweepWindows();

  /// The next window, samples [first(), first() + size()) of the sweep (valid until the next
  /// call), or null after the last, or once `cancel` is true (stop reading then).
  const SweepResult* next(const std::atomic<bool>* cancel = nullptr);
  /// The current window's first sample.
  std::size_t first() const;
  /// What the windows read so far found (the whole sweep's once next() returned null).
  const SweepSummary& summary() const;

private:
  SweepWindows();
  struct State;
  std::unique_ptr<State> m_state;
};

/// Runs the sweep. Fails only for an invalid mechanism, spec or selection; samples that cannot
/// be assembled are reported in the result (report, notAssembled, firstFailure).
Result<SweepResult> sweep(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request = {});

/// The same sweep written into `out`, reusing its columns' storage: repeated sweeps of one
/// size (a drag, an animation, a benchmark) allocate nothing per call beyond the solver's
/// scratch poses. On error `out` is left as it was. If `cancel` is given and becomes true
/// (another thread sets it), the sweep stops within a few samples with ErrorCode::Cancelled
/// and `out` holds a partial sweep: discard it.
std::optional<Error> sweepInto(const Mechanism& mechanism, const SweepSpec& spec, const SolveRequest& request,
                               SweepResult& out, const std::atomic<bool>* cancel = nullptr);

}  // namespace linkwright::kinematics
