// `linkwright-cli arm`: the two-link arm of seed 004 (or any other) with its tip on a straight
// line at constant speed, one row per time sample. A thin alias of analyze: the arm is a
// linkage like any other (a ground pivot, the tip driven along the line, the elbow an RRR
// joint: model/driven_linkages.h), swept on its time base by the same solver; this command
// only keeps the options and columns scripts written for it know. The stretches of the path
// outside the workspace come from their exact crossings with its annulus.

#include "app/cli/commands.h"

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/design/design.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

// Seed 004's arm is the example seed-arm: the same document analyze reads.
constexpr const char* kSeedArmName = "seed-arm";
constexpr long long kDefaultSamples = 101;
using k::kMaxSamples;  // the input domain's (validate.h)

// Point and link ids of makeTwoLinkArm's mechanism.
constexpr std::size_t kTip = 1;
constexpr std::size_t kElbow = 2;
constexpr std::size_t kUpper = 0;
constexpr std::size_t kForearm = 1;

struct ArmRequest {
  k::TwoLinkArm arm;
  k::Mechanism mechanism;  ///< makeTwoLinkArm's: O, tip on the line, elbow
  k::PolylinePath line;    ///< the tip's path, from --from-point to --to-point
  double speed = 0.0;      ///< of the tip along it, length unit / s
  k::SweepSpec spec;       ///< the time base: the tip at `speed` from the line's start
};

k::Error badValue(const std::string& option, const std::string& message) {
  return k::Error{k::ErrorCode::InvalidValue, option, message};
}

std::string pointText(const Eigen::Vector2d& p) { return "(" + formatShort(p.x()) + ", " + formatShort(p.y()) + ")"; }

// The time grid: --samples N evenly spaced over the path, or every --step-time seconds from
// 0, ending at the path's end when the step lands on it (as analyze's --step).
k::Result<std::pair<double, std::size_t>> timeGrid(const Invocation& inv, double duration) {
  if (inv.stepTime) {
    const double intervals = std::floor(duration / *inv.stepTime + 1e-9);
    if (intervals + 1.0 > static_cast<double>(kMaxSamples))
      return badValue("--step-time", "--step-time is too small: it would give " + formatShort(intervals + 1.0) +
                                         " rows (at most " + std::to_string(kMaxSamples) + ")");
    return std::pair{intervals * *inv.stepTime, static_cast<std::size_t>(intervals) + 1};
  }
  const long long n = inv.samples.value_or(kDefaultSamples);
  if (n > kMaxSamples)
    return badValue("--samples", "--samples must be between 2 and " + std::to_string(kMaxSamples) + " (got " +
                                     std::to_string(n) + ")");
  return std::pair{duration, static_cast<std::size_t>(n)};
}

// The option that sets a field checkArmPath names.
std::string optionFor(const std::string& field) {
  if (field == "speed") return "--speed";
  if (field.rfind("from.", 0) == 0) return "--from-point";
  if (field.rfind("to.", 0) == 0) return "--to-point";
  return "--arm";  // upper, forearm, or their spread
}

k::Result<ArmRequest> armRequest(const Invocation& inv) {
  k::TwoLinkArm arm;
  k::LinePath path;
  k::Branch elbow = k::Branch::Open;
  if (inv.example) {
    const auto seed = k::designForExample(kSeedArmName);
    if (*inv.example != kSeedArmName || !seed)
      return badValue("--example",
                      "--example: no arm example named '" + *inv.example + "' (arm has one: " + kSeedArmName + ")");
    if (inv.lengthUnit != "m")
      return badValue("--unit", "--unit: the " + std::string(kSeedArmName) +
                                    " example is in metres; give --arm, --from-point, "
                                    "--to-point and --speed without --example to work in " +
                                    inv.lengthUnit);
    const k::Mechanism& m = seed->mechanism;
    const auto& line = std::get<k::PolylinePath>(std::get<k::PathPoint>(m.points[kTip].definition).path);
    const auto& joint = std::get<k::RrrPoint>(m.points[kElbow].definition);
    arm = {joint.firstLength, joint.secondLength};
    path = {line.vertices.front(), line.vertices.back(), std::get<k::ConstantVelocity>(seed->time->law).velocity};
    elbow = joint.branch;
  }
  if (inv.arm) arm = {inv.arm->first, inv.arm->second};
  if (inv.fromPoint) path.from = *inv.fromPoint;
  if (inv.toPoint) path.to = *inv.toPoint;
  if (inv.speed) path.speed = *inv.speed;
  if (inv.elbow) elbow = *inv.elbow;
  if (auto e = k::checkArmPath(arm, path)) {
    const std::string option = optionFor(e->field);
    return badValue(option, option + ": " + e->message);
  }
  const double length = (path.to - path.from).norm();
  if (!(length > 0.0))
    return badValue("--to-point", "--to-point must differ from --from-point (both are " + pointText(path.from) + ")");
  ArmRequest r{arm, {}, k::PolylinePath{{path.from, path.to}}, path.speed, {}};
  auto mechanism = k::makeTwoLinkArm({arm.upper, arm.forearm, r.line, elbow, inv.lengthUnit});
  if (!mechanism) return badValue("--arm", "--arm: " + mechanism.error().message);
  r.mechanism = std::move(*mechanism);
  const auto grid = timeGrid(inv, length / path.speed);
  if (!grid) return grid.error();
  r.spec.samples = grid->second;
  r.spec.time = k::TimeBase{k::ConstantVelocity{0.0, path.speed}, 0.0, grid->first};
  return r;
}

enum class RowStatus { Ok, Singular, Unreachable };

struct ArmRow {
  double time = 0.0;
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();
  RowStatus status = RowStatus::Unreachable;
  k::ArmState state;  ///< angles unwrapped along the path
};

// The sweep's samples as the arm's rows; the tip wherever it is, reachable or not.
std::vector<ArmRow> armRows(const ArmRequest& r, const k::SweepResult& s) {
  std::vector<ArmRow> rows(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    ArmRow& row = rows[j];
    row.time = s.time[j];
    row.tip = k::pathAt(r.line, s.inputAngle[j]).point;
    row.status = s.ok(j) ? RowStatus::Ok : s.assembled(j) ? RowStatus::Singular : RowStatus::Unreachable;
    if (row.status == RowStatus::Unreachable) continue;
    row.state = {s.linkAngle[kUpper][j], s.linkAngle[kForearm][j], s.linkOmega[kUpper][j], s.linkOmega[kForearm][j],
                 s.linkAlpha[kUpper][j], s.linkAlpha[kForearm][j], s.position[kElbow][j]};
  }
  return rows;
}

enum class CellKind { Time, Tip, Joint, Rate };

struct ArmColumn {
  std::string name;
  CellKind kind;
  double (*value)(const ArmRow&);
};

std::vector<ArmColumn> armColumns(const std::string& u) {
  return {
      {"time_s", CellKind::Time, [](const ArmRow& r) { return r.time; }},
      {"tip_x_" + u, CellKind::Tip, [](const ArmRow& r) { return r.tip.x(); }},
      {"tip_y_" + u, CellKind::Tip, [](const ArmRow& r) { return r.tip.y(); }},
      {"upper_angle_deg", CellKind::Joint, [](const ArmRow& r) { return k::radToDeg(r.state.upperAngle); }},
      {"forearm_angle_deg", CellKind::Joint, [](const ArmRow& r) { return k::radToDeg(r.state.forearmAngle); }},
      {"upper_omega_rad_s", CellKind::Rate, [](const ArmRow& r) { return r.state.upperOmega; }},
      {"forearm_omega_rad_s", CellKind::Rate, [](const ArmRow& r) { return r.state.forearmOmega; }},
      {"upper_alpha_rad_s2", CellKind::Rate, [](const ArmRow& r) { return r.state.upperAlpha; }},
      {"forearm_alpha_rad_s2", CellKind::Rate, [](const ArmRow& r) { return r.state.forearmAlpha; }},
      {"elbow_x_" + u, CellKind::Joint, [](const ArmRow& r) { return r.state.elbow.x(); }},
      {"elbow_y_" + u, CellKind::Joint, [](const ArmRow& r) { return r.state.elbow.y(); }},
  };
}

// Joint cells (angles, elbow) exist where the tip can be reached, rates only off the
// stretched and folded poses; the tip and the time always.
bool defined(const ArmColumn& c, const ArmRow& r) {
  if (c.kind == CellKind::Time || c.kind == CellKind::Tip) return true;
  if (c.kind == CellKind::Rate) return r.status == RowStatus::Ok;
  return r.status != RowStatus::Unreachable;
}

// The time column is the requested grid: 12 significant digits print 0.03 as "0.03".
std::string csvCell(const ArmColumn& c, const ArmRow& r) {
  if (!defined(c, r)) return {};
  return c.kind == CellKind::Time ? formatShort(c.value(r), 12) : k::formatDouble(c.value(r));
}

void writeCsv(std::ostream& out, const std::vector<ArmColumn>& columns, const std::vector<ArmRow>& rows) {
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << k::io::csvField(columns[c].name);
  out << "\r\n";
  for (const ArmRow& row : rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << csvCell(columns[c], row);
    out << "\r\n";
  }
}

void writeTable(std::ostream& out, const std::vector<ArmColumn>& columns, const std::vector<ArmRow>& rows) {
  constexpr int kDecimals = 4;
  std::vector<int> widths;
  for (const ArmColumn& c : columns) {
    widths.push_back(std::max(static_cast<int>(c.name.size()), kDecimals + 8));
    out << (widths.size() > 1 ? "  " : "") << std::setw(widths.back()) << c.name;
  }
  out << "\n";
  for (const ArmRow& row : rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string text = defined(columns[c], row)            ? k::formatFixed(columns[c].value(row), kDecimals)
                               : row.status == RowStatus::Singular ? "singular"
                                                                   : "unreachable";
      out << (c ? "  " : "") << std::setw(widths[c]) << text;
    }
    out << "\n";
  }
}

// The stretches of the path outside the workspace, exactly, and the samples in them.
bool reportUnreachable(const ArmRequest& r, const std::vector<ArmRow>& rows, const std::string& u, std::ostream& err) {
  const auto outside = k::pathOutsideAnnulus(r.line, Eigen::Vector2d::Zero(), std::abs(r.arm.upper - r.arm.forearm),
                                             r.arm.upper + r.arm.forearm);
  const std::size_t missed = static_cast<std::size_t>(
      std::count_if(rows.begin(), rows.end(), [](const ArmRow& row) { return row.status == RowStatus::Unreachable; }));
  if (outside.empty() && missed == 0) return false;
  err << "linkwright-cli: the tip leaves the arm's workspace (" << formatShort(std::abs(r.arm.upper - r.arm.forearm))
      << " " << u << " to " << formatShort(r.arm.upper + r.arm.forearm) << " " << u << " from the shoulder): " << missed
      << " of " << rows.size() << " samples cannot be reached; their joint cells are left empty.\n";
  for (const auto& [from, to] : outside)
    err << "  unreachable for t = " << formatShort(from / r.speed) << " s to " << formatShort(to / r.speed)
        << " s (exact): tip from " << pointText(k::pathAt(r.line, from).point) << " " << u << " to "
        << pointText(k::pathAt(r.line, to).point) << " " << u << "\n";
  return true;
}

void reportSingular(const ArmRequest& r, const std::vector<ArmRow>& rows, const std::string& u, std::ostream& err) {
  for (const ArmRow& row : rows) {
    if (row.status != RowStatus::Singular) continue;
    const double reach = row.tip.norm();
    const double outer = r.arm.upper + r.arm.forearm, inner = std::abs(r.arm.upper - r.arm.forearm);
    const bool stretched = std::abs(reach - outer) < std::abs(reach - inner);
    err << "linkwright-cli: note: the arm is " << (stretched ? "stretched out" : "folded")
        << " at t = " << formatShort(row.time) << " s, tip " << pointText(row.tip) << " " << u
        << ": joint rates are undefined there (ω and α cells left empty)\n";
  }
}

}  // namespace

ExitCode runArm(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto request = armRequest(inv);
  if (!request) {
    err << "linkwright-cli: " << request.error().message << "\n";
    return ExitCode::BadInput;
  }
  const auto swept = k::sweep(request->mechanism, request->spec);
  if (!swept) {
    err << "linkwright-cli: " << swept.error().message << "\n";
    return ExitCode::BadInput;
  }
  const std::vector<ArmRow> rows = armRows(*request, *swept);
  const std::vector<ArmColumn> columns = armColumns(inv.lengthUnit);
  std::ostringstream text;
  if (inv.tableFormat) writeTable(text, columns, rows);
  else writeCsv(text, columns, rows);
  if (inv.outputFile) {
    if (auto problem = kinematics::io::writeFileSafely(*inv.outputFile, text.str())) {
      err << "linkwright-cli: " << problem->message << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << text.str() << std::flush;
  }
  reportSingular(*request, rows, inv.lengthUnit, err);
  return reportUnreachable(*request, rows, inv.lengthUnit, err) ? ExitCode::NotAssemblable : ExitCode::Success;
}

}  // namespace linkwright::cli
