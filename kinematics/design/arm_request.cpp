#include "kinematics/design/arm_request.h"

#include "kinematics/design/design.h"
#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/sweep.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// Seed 004's arm is the example seed-arm: the same document analyze reads.
constexpr const char* kSeedArmName = "seed-arm";

// Point and link ids of makeTwoLinkArm's mechanism.
constexpr std::size_t kTip = 1;
constexpr std::size_t kElbow = 2;
constexpr std::size_t kUpper = 0;
constexpr std::size_t kForearm = 1;

std::string pointText(const Eigen::Vector2d& p) { return "(" + formatShort(p.x()) + ", " + formatShort(p.y()) + ")"; }

// A refusal of the field `key`: the field's name as the front end spells it, then `rest`.
Error refusal(const ArmRequest& request, const std::string& key, const std::string& rest) {
  const std::string name = fieldName(key, request.frontEnd);
  return Error{ErrorCode::InvalidValue, name, name + rest};
}

// The field whose value checkArmPath refused.
std::string keyFor(const std::string& field) {
  if (field == "speed") return "speed";
  if (field.rfind("from.", 0) == 0) return "from_point";
  if (field.rfind("to.", 0) == 0) return "to_point";
  return "arm";  // upper, forearm, or their spread
}

// The time grid: `samples` rows evenly spaced over the path, or one every `stepTime` seconds
// from 0, ending at the path's end when the step lands on it (as analyze's --step).
Result<std::pair<double, std::size_t>> timeGrid(const ArmRequest& request, double duration) {
  if (request.stepTime) {
    const double intervals = std::floor(duration / *request.stepTime + 1e-9);
    if (intervals + 1.0 > static_cast<double>(kMaxSamples))
      return refusal(request, "step_time",
                     " is too small: it would give " + formatShort(intervals + 1.0) + " rows (at most " +
                         std::to_string(kMaxSamples) + ")");
    return std::pair{intervals * *request.stepTime, static_cast<std::size_t>(intervals) + 1};
  }
  const long long n = request.samples.value_or(kDefaultArmSamples);
  if (n < 2 || n > kMaxSamples)
    return refusal(request, "samples",
                   " must be between 2 and " + std::to_string(kMaxSamples) + " (got " + std::to_string(n) + ")");
  return std::pair{duration, static_cast<std::size_t>(n)};
}

}  // namespace

Result<ArmRun> runArm(const ArmRequest& request, const ArmRowSink& sink) {
  const std::string& unit = request.lengthUnit;
  if (unit.empty() ||
      unit.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") != std::string::npos)
    return refusal(request, "unit", " must be a unit name made of letters, e.g. mm, m, in (got '" + unit + "')");
  TwoLinkArm arm;
  LinePath path;
  Branch elbow = Branch::Open;
  if (request.example) {
    const auto seed = designForExample(kSeedArmName);
    if (*request.example != kSeedArmName || !seed)
      return refusal(request, "example",
                     ": no arm example named '" + *request.example + "' (arm has one: " + kSeedArmName + ")");
    if (request.lengthUnit != "m")
      return refusal(request, "unit",
                     ": the " + std::string(kSeedArmName) + " example is in metres; give " +
                         fieldName("arm", request.frontEnd) + ", " + fieldName("from_point", request.frontEnd) + ", " +
                         fieldName("to_point", request.frontEnd) + " and " + fieldName("speed", request.frontEnd) +
                         " without " + fieldName("example", request.frontEnd) + " to work in " + request.lengthUnit);
    const Mechanism& m = seed->mechanism;
    const auto& line = std::get<PolylinePath>(std::get<PathPoint>(m.points[kTip].definition).path);
    const auto& joint = std::get<RrrPoint>(m.points[kElbow].definition);
    arm = {joint.firstLength, joint.secondLength};
    path = {line.vertices.front(), line.vertices.back(), std::get<ConstantVelocity>(seed->time->law).velocity};
    elbow = joint.branch;
  }
  if (request.arm) arm = {request.arm->first, request.arm->second};
  if (request.fromPoint) path.from = *request.fromPoint;
  if (request.toPoint) path.to = *request.toPoint;
  if (request.speed) path.speed = *request.speed;
  if (request.elbow) elbow = *request.elbow;
  if (auto e = checkArmPath(arm, path)) return refusal(request, keyFor(e->field), ": " + e->message);
  const double length = (path.to - path.from).norm();
  if (!(length > 0.0))
    return refusal(
        request, "to_point",
        " must differ from " + fieldName("from_point", request.frontEnd) + " (both are " + pointText(path.from) + ")");
  // Refused here, not by the sweep's time base, so the message names the speed typed.
  if (!(length / path.speed <= kMaxTime))
    return refusal(request, "speed",
                   " is too slow: the path of " + formatShort(length) + " " + unit + " would take " +
                       formatShort(length / path.speed) + " s, beyond " + formatShort(kMaxTime) +
                       " s (the speed must be at least " + formatShort(length / kMaxTime) + " " + unit + "/s)");
  ArmRun run{arm, PolylinePath{{path.from, path.to}}, path.speed, request.lengthUnit, {}, {}};
  auto mechanism = makeTwoLinkArm({arm.upper, arm.forearm, run.line, elbow, request.lengthUnit});
  if (!mechanism) return refusal(request, "arm", ": " + mechanism.error().message);
  const auto grid = timeGrid(request, length / path.speed);
  if (!grid) return grid.error();
  SweepSpec spec;
  spec.samples = grid->second;
  spec.time = TimeBase{ConstantVelocity{0.0, path.speed}, 0.0, grid->first};
  std::vector<ArmRow> rows;
  const auto swept = sweepInWindows(*mechanism, spec, {}, kSweepWindow, [&](const SweepResult& s, std::size_t) {
    rows.resize(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) {
      ArmRow& row = rows[j];
      row.time = s.time[j];
      row.tip = pathAt(run.line, s.inputAngle[j]).point;
      row.reach = s.ok(j) ? ArmReach::Ok : s.assembled(j) ? ArmReach::Singular : ArmReach::Unreachable;
      row.state = {};
      if (row.reach == ArmReach::Unreachable) {
        ++run.unreachable;
        continue;
      }
      row.state = {s.linkAngle[kUpper][j], s.linkAngle[kForearm][j], s.linkOmega[kUpper][j], s.linkOmega[kForearm][j],
                   s.linkAlpha[kUpper][j], s.linkAlpha[kForearm][j], s.position[kElbow][j]};
      if (row.reach == ArmReach::Singular && run.singular++ < kArmSingularRowsNamed) run.singularRows.push_back(row);
    }
    run.samples += rows.size();
    return sink(rows, spec.samples);
  });
  if (!swept) return swept.error();
  run.outside =
      pathOutsideAnnulus(run.line, Eigen::Vector2d::Zero(), std::abs(arm.upper - arm.forearm), arm.upper + arm.forearm);
  return run;
}

Result<ArmRun> runArm(const ArmRequest& request) {
  std::vector<ArmRow> kept;
  auto run = runArm(request, [&](const std::vector<ArmRow>& rows, std::size_t rowsInAll) {
    kept.reserve(rowsInAll);
    kept.insert(kept.end(), rows.begin(), rows.end());
    return true;
  });
  if (run) run.value().rows = std::move(kept);
  return run;
}

std::vector<ArmColumn> armColumns(const std::string& u) {
  using Kind = ArmColumn::Kind;
  return {
      {"time_s", Kind::Time, [](const ArmRow& r) { return r.time; }},
      {"tip_x_" + u, Kind::Tip, [](const ArmRow& r) { return r.tip.x(); }},
      {"tip_y_" + u, Kind::Tip, [](const ArmRow& r) { return r.tip.y(); }},
      {"upper_angle_deg", Kind::Joint, [](const ArmRow& r) { return radToDeg(r.state.upperAngle); }},
      {"forearm_angle_deg", Kind::Joint, [](const ArmRow& r) { return radToDeg(r.state.forearmAngle); }},
      {"upper_omega_rad_s", Kind::Rate, [](const ArmRow& r) { return r.state.upperOmega; }},
      {"forearm_omega_rad_s", Kind::Rate, [](const ArmRow& r) { return r.state.forearmOmega; }},
      {"upper_alpha_rad_s2", Kind::Rate, [](const ArmRow& r) { return r.state.upperAlpha; }},
      {"forearm_alpha_rad_s2", Kind::Rate, [](const ArmRow& r) { return r.state.forearmAlpha; }},
      {"elbow_x_" + u, Kind::Joint, [](const ArmRow& r) { return r.state.elbow.x(); }},
      {"elbow_y_" + u, Kind::Joint, [](const ArmRow& r) { return r.state.elbow.y(); }},
  };
}

bool armCellDefined(const ArmColumn& column, const ArmRow& row) {
  if (column.kind == ArmColumn::Kind::Time || column.kind == ArmColumn::Kind::Tip) return true;
  if (column.kind == ArmColumn::Kind::Rate) return row.reach == ArmReach::Ok;
  return row.reach != ArmReach::Unreachable;
}

bool armLeavesWorkspace(const ArmRun& run) { return !run.outside.empty() || run.unreachable > 0; }

std::vector<std::string> armNotes(const ArmRun& run) {
  std::vector<std::string> notes;
  const std::string& u = run.lengthUnit;
  const double outer = run.arm.upper + run.arm.forearm, inner = std::abs(run.arm.upper - run.arm.forearm);
  for (const ArmRow& row : run.singularRows) {
    const double reach = row.tip.norm();
    const bool stretched = std::abs(reach - outer) < std::abs(reach - inner);
    notes.push_back("note: the arm is " + std::string(stretched ? "stretched out" : "folded") +
                    " at t = " + formatShort(row.time) + " s, tip " + pointText(row.tip) + " " + u +
                    ": joint rates are undefined there (ω and α cells left empty)");
  }
  if (run.singular > run.singularRows.size())
    notes.push_back("note: the arm is stretched out or folded at " +
                    std::to_string(run.singular - run.singularRows.size()) + " more samples (joint rates left empty)");
  if (!armLeavesWorkspace(run)) return notes;
  std::string text = "the tip leaves the arm's workspace (" + formatShort(inner) + " " + u + " to " +
                     formatShort(outer) + " " + u + " from the shoulder): " + std::to_string(run.unreachable) + " of " +
                     std::to_string(run.samples) + " samples cannot be reached; their joint cells are left empty.";
  for (const auto& [from, to] : run.outside)
    text += "\n  unreachable for t = " + formatShort(from / run.speed) + " s to " + formatShort(to / run.speed) +
            " s (exact): tip from " + pointText(pathAt(run.line, from).point) + " " + u + " to " +
            pointText(pathAt(run.line, to).point) + " " + u;
  notes.push_back(std::move(text));
  return notes;
}

}  // namespace linkwright::kinematics
