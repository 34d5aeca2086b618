// `linkwright-cli arm`: the two-link arm of seed 004 (or any other) with its tip on a straight
// line at constant speed, one row per time sample: the joints from the core's inverse
// kinematics (kinematics/analysis/two_link_arm.h), the stretches of the path outside the
// workspace from its exact line–circle crossings.

#include "app/cli/atomic_file.h"
#include "app/cli/commands.h"

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/number_format.h"
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
using k::io::formatShort;

// Seed 004: r1 = 0.3 m, r2 = 0.2 m, tip from (0.3, 0) to (0, 0.3) m at 2 m/s. Its MATLAB steps
// x by 0.003 m: 101 points. Its plots have θ1 rising from −39° to 51°: the elbow down.
constexpr const char* kSeedArmName = "seed-arm";
const k::TwoLinkArm kSeedArm{0.3, 0.2};
const k::LinePath kSeedPath{{0.3, 0.0}, {0.0, 0.3}, 2.0};
constexpr long long kDefaultSamples = 101;
using k::kMaxSamples;  // the input domain's (validate.h)

struct ArmRequest {
  k::TwoLinkArm arm;
  k::LinePath path;
  k::Branch elbow = k::Branch::Open;
  double duration = 0.0;      ///< s
  Eigen::Vector2d velocity;   ///< of the tip, length unit / s
  std::vector<double> times;  ///< s
};

k::Error badValue(const std::string& option, const std::string& message) {
  return k::Error{k::ErrorCode::InvalidValue, option, message};
}

std::string pointText(const Eigen::Vector2d& p) { return "(" + formatShort(p.x()) + ", " + formatShort(p.y()) + ")"; }

// The time grid: --samples N evenly spaced (as followLine spaces them), or every --step-time
// seconds from 0, ending at the path's end when the step lands on it (as analyze's --step).
k::Result<std::vector<double>> timeGrid(const Invocation& inv, double duration) {
  std::vector<double> times;
  if (inv.stepTime) {
    const double intervals = std::floor(duration / *inv.stepTime + 1e-9);
    if (intervals + 1.0 > static_cast<double>(kMaxSamples))
      return badValue("--step-time", "--step-time is too small: it would give " + formatShort(intervals + 1.0) +
                                         " rows (at most " + std::to_string(kMaxSamples) + ")");
    for (long long j = 0; j <= static_cast<long long>(intervals); ++j)
      times.push_back(static_cast<double>(j) * *inv.stepTime);
    return times;
  }
  const long long n = inv.samples.value_or(kDefaultSamples);
  if (n > kMaxSamples)
    return badValue("--samples", "--samples must be between 2 and " + std::to_string(kMaxSamples) + " (got " +
                                     std::to_string(n) + ")");
  for (long long j = 0; j < n; ++j) times.push_back(duration * static_cast<double>(j) / static_cast<double>(n - 1));
  return times;
}

// The option that sets a field checkArmPath names.
std::string optionFor(const std::string& field) {
  if (field == "speed") return "--speed";
  if (field.rfind("from.", 0) == 0) return "--from-point";
  if (field.rfind("to.", 0) == 0) return "--to-point";
  return "--arm";  // upper, forearm, or their spread
}

k::Result<ArmRequest> armRequest(const Invocation& inv) {
  ArmRequest r;
  if (inv.example) {
    if (*inv.example != kSeedArmName)
      return badValue("--example",
                      "--example: no arm example named '" + *inv.example + "' (arm has one: " + kSeedArmName + ")");
    if (inv.lengthUnit != "m")
      return badValue("--unit", "--unit: the " + std::string(kSeedArmName) +
                                    " example is in metres; give --arm, --from-point, "
                                    "--to-point and --speed without --example to work in " +
                                    inv.lengthUnit);
    r.arm = kSeedArm;
    r.path = kSeedPath;
    r.elbow = k::Branch::Crossed;
  }
  if (inv.arm) r.arm = {inv.arm->first, inv.arm->second};
  if (inv.fromPoint) r.path.from = *inv.fromPoint;
  if (inv.toPoint) r.path.to = *inv.toPoint;
  if (inv.speed) r.path.speed = *inv.speed;
  if (inv.elbow) r.elbow = *inv.elbow;
  if (auto e = k::checkArmPath(r.arm, r.path)) {
    const std::string option = optionFor(e->field);
    return badValue(option, option + ": " + e->message);
  }
  const double length = (r.path.to - r.path.from).norm();
  if (!(length > 0.0))
    return badValue("--to-point", "--to-point must differ from --from-point (both are " + pointText(r.path.from) + ")");
  // The same arithmetic as followLine, so a row equals the core's sample bit for bit.
  r.duration = length / r.path.speed;
  r.velocity = (r.path.to - r.path.from) / r.duration;
  auto times = timeGrid(inv, r.duration);
  if (!times) return times.error();
  r.times = std::move(*times);
  return r;
}

enum class RowStatus { Ok, Singular, Unreachable };

struct ArmRow {
  double time = 0.0;
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();
  RowStatus status = RowStatus::Unreachable;
  k::ArmState state;  ///< angles unwrapped along the path
};

std::vector<ArmRow> solveRows(const ArmRequest& r) {
  std::vector<ArmRow> rows;
  std::optional<std::pair<double, double>> last;  // the previous defined angles, for unwrapping
  for (const double t : r.times) {
    ArmRow row;
    row.time = t;
    row.tip = r.path.from + r.velocity * t;
    const auto full = k::solveTwoLinkArm(r.arm, r.elbow, row.tip, r.velocity);
    if (full) {
      row.status = RowStatus::Ok;
      row.state = *full;
    } else if (full.error().code == k::ErrorCode::Singular) {
      // Stretched or folded: the position exists, the rates do not.
      const auto position = k::solveTwoLinkArm(r.arm, r.elbow, row.tip);
      row.status = position ? RowStatus::Singular : RowStatus::Unreachable;
      if (position) row.state = *position;
    }
    if (row.status != RowStatus::Unreachable) {
      if (last) {
        row.state.upperAngle = last->first + std::remainder(row.state.upperAngle - last->first, 2.0 * k::kPi);
        row.state.forearmAngle = last->second + std::remainder(row.state.forearmAngle - last->second, 2.0 * k::kPi);
      }
      last = std::pair{row.state.upperAngle, row.state.forearmAngle};
    }
    rows.push_back(row);
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
  return c.kind == CellKind::Time ? formatShort(c.value(r), 12) : k::io::formatDouble(c.value(r));
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
      const std::string text = defined(columns[c], row) ? k::io::formatFixed(columns[c].value(row), kDecimals)
                               : row.status == RowStatus::Singular ? "singular"
                                                                   : "unreachable";
      out << (c ? "  " : "") << std::setw(widths[c]) << text;
    }
    out << "\n";
  }
}

// The stretches of the path outside the workspace, exactly, and the samples in them.
bool reportUnreachable(const ArmRequest& r, const std::vector<ArmRow>& rows, const std::string& u, std::ostream& err) {
  const auto exact = k::followLine(r.arm, r.elbow, r.path, 2);
  const std::size_t missed = static_cast<std::size_t>(
      std::count_if(rows.begin(), rows.end(), [](const ArmRow& row) { return row.status == RowStatus::Unreachable; }));
  if ((!exact || exact->unreachable.empty()) && missed == 0) return false;
  err << "linkwright-cli: the tip leaves the arm's workspace (" << formatShort(std::abs(r.arm.upper - r.arm.forearm))
      << " " << u << " to " << formatShort(r.arm.upper + r.arm.forearm) << " " << u << " from the shoulder): " << missed
      << " of " << rows.size() << " samples cannot be reached; their joint cells are left empty.\n";
  if (exact)
    for (const auto& [from, to] : exact->unreachable)
      err << "  unreachable for t = " << formatShort(from) << " s to " << formatShort(to) << " s (exact): tip from "
          << pointText(r.path.from + r.velocity * from) << " " << u << " to "
          << pointText(r.path.from + r.velocity * to) << " " << u << "\n";
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
  const std::vector<ArmRow> rows = solveRows(*request);
  const std::vector<ArmColumn> columns = armColumns(inv.lengthUnit);
  std::ostringstream text;
  if (inv.tableFormat) writeTable(text, columns, rows);
  else writeCsv(text, columns, rows);
  if (inv.outputFile) {
    if (auto problem = writeFileAtomically(*inv.outputFile, text.str())) {
      err << "linkwright-cli: " << *problem << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << text.str() << std::flush;
  }
  reportSingular(*request, rows, inv.lengthUnit, err);
  return reportUnreachable(*request, rows, inv.lengthUnit, err) ? ExitCode::NotAssemblable : ExitCode::Success;
}

}  // namespace linkwright::cli
