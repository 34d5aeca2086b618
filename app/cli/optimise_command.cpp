// `linkwright-cli optimise`: a linkage's dimensions changed to improve one objective
// (kinematics/tune/optimise_linkage.h) within ranges, keeping its Grashof class, branch,
// fixed pivots and its motion through the whole grid; the result written as a document through
// the one writer, and the objective before and after with the dimensions that changed printed
// as text, or as one JSON object.

#include "app/cli/commands.h"
#include "app/cli/progress.h"

#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/tune/optimise_linkage.h"

#include <cmath>
#include <ostream>
#include <sstream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

k::Error bad(const std::string& option, const std::string& message) {
  return k::Error{k::ErrorCode::InvalidValue, option, message};
}

// The target points of --objective path:FILE: the first two columns of a CSV (x, y in the
// linkage's length unit), header rows allowed.
k::Result<std::vector<Eigen::Vector2d>> readTargets(const std::string& file) {
  const auto text = k::io::readFileBounded(file, k::io::kMaxNumericTableBytes, "a table of target points");
  if (!text) return bad("--objective", "--objective: " + text.error().message);
  const auto table = k::io::readNumericTable(*text);
  if (!table) return bad("--objective", "--objective: " + file + ": " + table.error().message);
  std::vector<Eigen::Vector2d> targets;
  for (const k::io::NumericRow& row : table->rows) {
    if (row.cells.size() < 2 || !row.cells[0] || !row.cells[1])
      return bad("--objective", "--objective: " + file + " line " + std::to_string(row.line) +
                                    " needs a target's x and y in its first two columns");
    targets.emplace_back(*row.cells[0], *row.cells[1]);
  }
  return targets;
}

k::Result<k::OptimiseObjective> objectiveFor(const Invocation& inv) {
  const std::string& text = *inv.objective;
  k::OptimiseObjective o;
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string argument = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (kind == "peak-alpha" && !argument.empty()) {
    o.kind = k::ObjectiveKind::PeakAlpha;
    o.link = argument;
  } else if (kind == "transmission" && colon == std::string::npos) {
    o.kind = k::ObjectiveKind::Transmission;
  } else if (kind == "rms-torque" && colon == std::string::npos) {
    o.kind = k::ObjectiveKind::RmsTorque;
  } else if (kind == "path" && !argument.empty()) {
    o.kind = k::ObjectiveKind::Path;
    auto targets = readTargets(argument);
    if (!targets) return targets.error();
    o.targets = std::move(targets).value();
  } else {
    return bad(
        "--objective",
        "--objective must be peak-alpha:LINK, transmission, path:TARGETS.csv or rms-torque (got '" + text + "')");
  }
  if (inv.objectivePoint) o.point = *inv.objectivePoint;
  if (inv.pathMeasure) {
    if (*inv.pathMeasure != "worst" && *inv.pathMeasure != "rms")
      return bad("--path-measure", "--path-measure must be worst or rms (got '" + *inv.pathMeasure + "')");
    o.measure = *inv.pathMeasure == "rms" ? k::PathMeasure::Rms : k::PathMeasure::Worst;
  }
  return o;
}

k::OptimiseConstraints constraintsFor(const Invocation& inv) {
  k::OptimiseConstraints c;
  if (inv.lengthRangePercent) c.lengthRange = *inv.lengthRangePercent / 100.0;  // checked by the parser
  if (inv.fixPivots && *inv.fixPivots != "all") {
    c.fixedPivots.emplace();
    std::istringstream names(*inv.fixPivots == "none" ? "" : *inv.fixPivots);
    for (std::string name; std::getline(names, name, ',');) c.fixedPivots->push_back(name);
  }
  return c;
}

// The core's field as the option the user typed.
std::string optionOf(const std::string& field) {
  if (field.rfind("fixedPivots", 0) == 0) return "--fix-pivots";
  if (field == "evaluations") return "--evaluations";
  if (field == "starts") return "--starts";
  if (field.rfind("objective", 0) == 0 || field == "dynamics") return "--objective";
  return "";
}

// The objective's value as shown: μ in degrees, the others in their SI or length unit.
std::pair<double, std::string> shown(const k::OptimiseObjective& o, double value, const std::string& unit) {
  switch (o.kind) {
  case k::ObjectiveKind::PeakAlpha: return {value, "rad/s²"};
  case k::ObjectiveKind::Transmission: return {k::radToDeg(value), "°"};
  case k::ObjectiveKind::Path: return {value, unit};
  case k::ObjectiveKind::RmsTorque: return {value, "N·m"};
  }
  return {value, ""};
}

std::string grashofText(const std::optional<k::GrashofClass>& c) {
  return c ? std::string(k::toString(*c)) : std::string("none (not a four-bar)");
}

void printText(std::ostream& out, const k::LinkageOptimisation& r, const std::string& source, const Invocation& inv,
               std::uint32_t seed) {
  const std::string& unit = r.design.mechanism.lengthUnit;
  const auto [before, u] = shown(r.objective, r.before, unit);
  const auto after = shown(r.objective, r.after, unit).first;
  out << k::objectiveName(r.objective) << " of " << source << ": " << formatShort(before, 6) << " → "
      << formatShort(after, 6) << " " << u;
  if (before != 0.0)
    out << " (" << (after >= before ? "+" : "−") << formatShort(std::abs(after / before - 1.0) * 100.0, 3) << " %)";
  out << "\n"
      << r.evaluations << " designs measured, " << r.feasibleEvaluations << " keeping every constraint, from "
      << r.startsRun << " starts (seed " << seed << ")"
      << (r.improved ? "" : "; nothing better found, the design is written unchanged") << "; written to "
      << *inv.outputFile << "\n";
  const auto& c = r.constraints;
  out << "kept: "
      << (c.grashofBefore ? "Grashof class " + grashofText(c.grashofAfter) +
                                (c.grashofAfter == c.grashofBefore ? ", " : " (changed!), ")
                          : std::string())
      << (c.branchKept ? "branch" : "branch changed!") << ", "
      << (c.assembles ? "assembly over the whole grid" : "not assembled everywhere!") << ", "
      << (c.withinRanges ? "every dimension within its range" : "a dimension out of its range!") << ", "
      << (c.pivotsKept ? "fixed pivots unchanged" : "a fixed pivot moved!") << "\n";
  out << "dimensions (" << unit << "), start → optimised [range]:\n";
  for (std::size_t d = 0; d < r.dimensions.size(); ++d) {
    const k::OptimiseDimension& dim = r.dimensions[d];
    out << "  " << dim.dimension.name << ": ";
    if (dim.fixed) out << formatShort(dim.dimension.value, 6) << " (fixed)\n";
    else
      out << formatShort(dim.dimension.value, 6) << " → " << formatShort(r.values[d], 6) << " ["
          << formatShort(dim.lo, 6) << ", " << formatShort(dim.hi, 6) << "]"
          << (r.values[d] == dim.dimension.value ? " (unchanged)" : "") << "\n";
  }
}

void printJson(std::ostream& out, const k::LinkageOptimisation& r, const Invocation& inv, std::uint32_t seed) {
  const std::string& unit = r.design.mechanism.lengthUnit;
  const auto [before, u] = shown(r.objective, r.before, unit);
  k::io::JsonValue dims = k::io::JsonValue::array();
  for (std::size_t d = 0; d < r.dimensions.size(); ++d) {
    const k::OptimiseDimension& dim = r.dimensions[d];
    dims.push_back({{"name", dim.dimension.name},
                    {"before", dim.dimension.value},
                    {"after", r.values[d]},
                    {"lo", dim.lo},
                    {"hi", dim.hi},
                    {"fixed", dim.fixed}});
  }
  const auto& c = r.constraints;
  const auto grashof = [](const std::optional<k::GrashofClass>& g) {
    return g ? k::io::JsonValue(std::string(k::toString(*g))) : k::io::JsonValue(nullptr);
  };
  out << k::io::JsonValue{{"objective", k::objectiveName(r.objective)},
                          {"unit", u},
                          {"before", before},
                          {"after", shown(r.objective, r.after, unit).first},
                          {"improved", r.improved},
                          {"evaluations", r.evaluations},
                          {"feasible_evaluations", r.feasibleEvaluations},
                          {"starts", r.startsRun},
                          {"seed", static_cast<double>(seed)},
                          {"grashof_before", grashof(c.grashofBefore)},
                          {"grashof_after", grashof(c.grashofAfter)},
                          {"branch_kept", c.branchKept},
                          {"assembles", c.assembles},
                          {"within_ranges", c.withinRanges},
                          {"pivots_kept", c.pivotsKept},
                          {"length_unit", unit},
                          {"dimensions", dims},
                          {"output", *inv.outputFile}}
             .dump(2)
      << "\n";
}

}  // namespace

ExitCode runOptimise(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto design = resolveDesign(inv);
  if (!design) {
    err << "linkwright-cli: " << design.error().message << "\n";
    return ExitCode::BadInput;
  }
  auto objective = objectiveFor(inv);
  if (!objective) {
    err << "linkwright-cli: " << objective.error().message << "\n";
    return ExitCode::BadInput;
  }
  k::OptimiseRequest request;
  request.objective = std::move(objective).value();
  request.constraints = constraintsFor(inv);
  if (inv.seed) request.options.seed = static_cast<std::uint32_t>(*inv.seed);
  if (inv.evaluations) request.options.evaluations = static_cast<int>(*inv.evaluations);
  if (inv.starts) request.options.starts = static_cast<int>(*inv.starts);
  Progress progress(err, "optimise", "designs");
  const auto result = k::optimiseLinkage(*design, request, nullptr, [&](int done, int total) {
    progress.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
  });
  if (!result) {
    const k::Error& e = result.error();
    const std::string option = optionOf(e.field);
    std::string message = e.message;
    // The core names its field first ("evaluations must …", "objective.link: …"): the option
    // typed stands in its place.
    if (!option.empty() && message.rfind(e.field, 0) == 0) message = option + message.substr(e.field.size());
    else if (!option.empty()) message = option + ": " + message;
    err << "linkwright-cli: " << message << "\n";
    return e.code == k::ErrorCode::NotAssemblable ? ExitCode::NotAssemblable : ExitCode::BadInput;
  }
  if (auto e = k::io::writeFileSafely(*inv.outputFile, k::io::writeDocument(result->design))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  const std::string source = inv.example        ? "the example " + *inv.example
                             : inv.documentPath ? *inv.documentPath
                                                : std::string("--fourbar");
  if (inv.json) printJson(out, *result, inv, request.options.seed);
  else printText(out, *result, source, inv, request.options.seed);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
