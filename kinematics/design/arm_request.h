#pragma once
// `arm` as one request for every front end: the two-link arm of seed 004 (or any other) with its
// tip on a straight line at constant speed, one row per time sample. The arm is a linkage like
// any other (a ground pivot, the tip driven along the line, the elbow an RRR joint:
// model/driven_linkages.h), swept on its time base by the same solver; the request keeps the
// fields and columns scripts written for it know, and the stretches of the path outside the
// workspace come from their exact crossings with its annulus. linkwright-cli arm and Python's
// linkwright.arm fill it alike; kinematics/io/arm_table.h writes its rows.

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::kinematics {

/// What an arm run is asked for. Unset geometry is the seed-arm example's when `example` is
/// given, else refused by checkArmPath; the grid is `samples` rows (default 101) over the path,
/// or one every `stepTime` seconds.
struct ArmRequest {
  std::optional<std::string> example;                 ///< only "seed-arm" (in metres)
  std::optional<std::pair<double, double>> arm;       ///< upper, forearm lengths
  std::optional<Eigen::Vector2d> fromPoint, toPoint;  ///< the tip's line
  std::optional<double> speed;                        ///< of the tip along it, length unit / s
  std::optional<Branch> elbow;                        ///< Open: elbow down (the example's)
  std::optional<long long> samples;                   ///< rows, 2 to kMaxSamples
  std::optional<double> stepTime;                     ///< s between rows, instead of samples
  std::string lengthUnit = "m";
  FrontEnd frontEnd = FrontEnd::Cli;  ///< who asked: the spelling of the fields in refusals
};

inline constexpr long long kDefaultArmSamples = 101;

/// Where a row's tip is for the arm.
enum class ArmReach { Ok, Singular, Unreachable };

struct ArmRow {
  double time = 0.0;
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();
  ArmReach reach = ArmReach::Unreachable;
  ArmState state;  ///< angles unwrapped along the path; meaningful unless Unreachable
};

/// The singular rows an arm run names in its notes; the rest are counted.
inline constexpr std::size_t kArmSingularRowsNamed = 20;

/// The run: what to say of its rows, and the rows themselves unless they were streamed.
struct ArmRun {
  TwoLinkArm arm;
  PolylinePath line;  ///< the tip's path, from fromPoint to toPoint
  double speed = 0.0;
  std::string lengthUnit;
  std::vector<ArmRow> rows;  ///< every row, from runArm(request); empty when they went to a sink
  /// The stretches of the path outside the workspace, exactly, as path coordinates (from, to).
  std::vector<std::pair<double, double>> outside;
  std::size_t samples = 0;           ///< rows in the run
  std::size_t unreachable = 0;       ///< rows whose tip the arm cannot reach
  std::size_t singular = 0;          ///< rows where the arm is stretched out or folded
  std::vector<ArmRow> singularRows;  ///< the first kArmSingularRowsNamed of them
};

/// A window of consecutive rows, in order, and how many rows the run has in all (the same in
/// every window, so the first can size what the rows go into); returns false to stop the run
/// (cancelled).
using ArmRowSink = std::function<bool(const std::vector<ArmRow>& rows, std::size_t rowsInAll)>;

/// The run the request asks for, its rows handed to `sink` a window at a time, so that memory
/// does not grow with `samples` (10⁷ rows are written from a few MB); the returned run holds no
/// rows. Errors, all before the first window, name the field as the front end spells it
/// ("--step-time", "step_time"): the example, the unit with an example, the arm and line
/// (checkArmPath), the grid; ErrorCode::Cancelled when the sink stopped it.
Result<ArmRun> runArm(const ArmRequest& request, const ArmRowSink& sink);

/// The same run with every row kept in `rows`.
Result<ArmRun> runArm(const ArmRequest& request);

/// One column of the arm's table: its name with the unit, and its value in a row.
struct ArmColumn {
  enum class Kind { Time, Tip, Joint, Rate };
  std::string name;  ///< "tip_x_m", "upper_omega_rad_s"
  Kind kind;
  double (*value)(const ArmRow&);
};

/// The columns, written once: time_s, tip_x/y, upper/forearm angle (deg), ω, α, elbow_x/y.
std::vector<ArmColumn> armColumns(const std::string& lengthUnit);

/// Whether the column has a value in the row: joint cells where the tip can be reached, rate
/// cells off the stretched and folded poses, the tip and the time always.
bool armCellDefined(const ArmColumn& column, const ArmRow& row);

/// The sentences the CLI writes on stderr and Python warns with: one per named singular row
/// ("the arm is stretched out at t = … s …: joint rates are undefined there"; the rest counted),
/// then the unreachable samples and each stretch outside the workspace with its exact times.
/// Empty when none.
std::vector<std::string> armNotes(const ArmRun& run);

/// Whether some sample cannot be reached, or the path leaves the workspace.
bool armLeavesWorkspace(const ArmRun& run);

}  // namespace linkwright::kinematics
