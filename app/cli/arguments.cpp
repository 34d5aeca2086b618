#include "app/cli/arguments.h"
#include "app/cli/compare_options.h"
#include "app/cli/option_values.h"

#include "kinematics/design/balance_request.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/tune/optimise_linkage.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <tuple>

namespace linkwright::cli {

const std::vector<kinematics::RequestField>& requestFieldsOf(Command command) {
  static const std::vector<kinematics::RequestField> none;
  return command == Command::Machine ? kinematics::machineFields() : none;
}

namespace {

using kinematics::Error;

const std::set<std::string>& optionsOf(Command command) {
  static const std::set<std::string> analyze{
      "--fourbar", "--example",  "--unit",      "--rpm",       "--omega",   "--alpha",
      "--from",    "--to",       "--step",      "--samples",   "--branch",  "--coupler-point",
      "-o",        "--output",   "--format",    "--forces",    "--law",     "--ramp-time",
      "--rise",    "--duration", "--law-table", "--from-time", "--to-time", "--step-time"};
  static const std::set<std::string> extremes{
      "--fourbar", "--example",  "--unit",      "--rpm",       "--omega",         "--alpha",    "--from",
      "--to",      "--step",     "--samples",   "--branch",    "--coupler-point", "--law",      "--ramp-time",
      "--rise",    "--duration", "--law-table", "--from-time", "--to-time",       "--step-time"};
  static const std::set<std::string> classify{"--fourbar", "--example", "--unit", "--branch", "--json"};
  static const std::set<std::string> arm{"--example", "--arm",     "--from-point", "--to-point",
                                         "--speed",   "--samples", "--step-time",  "--elbow",
                                         "--unit",    "-o",        "--output",     "--format"};
  static const std::set<std::string> centres{"--fourbar", "--example", "--unit", "--branch", "--at"};
  static const std::set<std::string> dxf{"--fourbar", "--example", "--unit",  "--branch", "--coupler-point",
                                         "--at",      "--hole",    "--width", "-o",       "--output"};
  static const std::set<std::string> report{"--fourbar",       "--example", "--unit", "--branch",
                                            "--coupler-point", "--at",      "--step", "--paper",
                                            "--rates",         "--angles",  "-o",     "--output"};
  static const std::set<std::string> polygon{"--fourbar", "--example", "--unit",  "--branch", "--at",
                                             "--rpm",     "--omega",   "--alpha", "--json"};
  static const std::set<std::string> inversions{"--fourbar", "--example", "--unit", "--branch", "--json"};
  static const std::set<std::string> accuracy{"--example", "-o", "--output", "--svg"};
  static const std::set<std::string> compare{"--fourbar", "--example",   "--unit",  "--branch", "--coupler-point",
                                             "--rpm",     "--omega",     "--alpha", "--from",   "--map",
                                             "--offset",  "--tolerance", "--json"};
  static const std::set<std::string> machine = [] {
    std::set<std::string> options{"--example", "--json"};
    for (const auto& field : requestFieldsOf(Command::Machine))
      options.insert(kinematics::fieldName(field, kinematics::FrontEnd::Cli));
    return options;
  }();
  static const std::set<std::string> balance{"--example", "-o",       "--output",        "--fraction",
                                             "--radius",  "--spring", "--spring-search", "--json"};
  static const std::set<std::string> cognates{"--fourbar", "--example", "--unit", "--coupler-point",
                                              "-o",        "--output",  "--json"};
  static const std::set<std::string> tolerance{"--fourbar", "--example", "--unit",  "--branch",    "--coupler-point",
                                               "--rpm",     "--omega",   "--alpha", "--from",      "--to",
                                               "--step",    "--samples", "--at",    "--tolerance", "--mc-samples",
                                               "--seed",    "--json",    "-o",      "--output",    "--tolerance-of"};
  static const std::set<std::string> optimise{"--example",      "--objective",  "--point", "--path-measure",
                                              "--length-range", "--fix-pivots", "--seed",  "--evaluations",
                                              "--starts",       "--json",       "-o",      "--output"};
  static const std::set<std::string> none{};
  switch (command) {
  case Command::Analyze: return analyze;
  case Command::Classify: return classify;
  case Command::Extremes: return extremes;
  case Command::Arm: return arm;
  case Command::Centres: return centres;
  case Command::Polygon: return polygon;
  case Command::Inversions: return inversions;
  case Command::Accuracy: return accuracy;
  case Command::Dxf: return dxf;
  case Command::Report: return report;
  case Command::Compare: return compare;
  case Command::Machine: return machine;
  case Command::Balance: return balance;
  case Command::Cognates: return cognates;
  case Command::Tolerance: return tolerance;
  case Command::Optimise: return optimise;
  default: return none;
  }
}

const char* commandName(Command command) {
  switch (command) {
  case Command::Analyze: return "analyze";
  case Command::Classify: return "classify";
  case Command::Extremes: return "extremes";
  case Command::Examples: return "examples";
  case Command::Arm: return "arm";
  case Command::Centres: return "centres";
  case Command::Polygon: return "polygon";
  case Command::Inversions: return "inversions";
  case Command::Accuracy: return "accuracy";
  case Command::Dxf: return "dxf";
  case Command::Report: return "report";
  case Command::Compare: return "compare";
  case Command::Machine: return "machine";
  case Command::Balance: return "balance";
  case Command::Cognates: return "cognates";
  case Command::Tolerance: return "tolerance";
  case Command::Optimise: return "optimise";
  case Command::Atlas: return "atlas";
  default: return "linkwright-cli";
  }
}

bool takesValue(const std::string& option) { return option != "--json" && option != "--forces"; }

// A number that must be positive and finite (a speed, a time step).
std::optional<Error> positive(std::optional<double>& target, const std::string& option, const std::string& value) {
  const auto parsed = parseNumber(value);
  if (!parsed) return usage(option, option + ": '" + value + "' is not a number");
  if (!(std::isfinite(*parsed) && *parsed > 0.0))
    return usage(option, option + " must be positive and finite (got " + kinematics::formatNumber(*parsed) + ")");
  target = *parsed;
  return std::nullopt;
}

// A length typed for a drawing (a hole's diameter, a plate's width): within the lengths a
// linkage may have (model/validate.h), so a DXF never holds 300-digit coordinates.
std::optional<Error> drawingLength(std::optional<double>& target, const std::string& option, const std::string& value) {
  if (auto e = positive(target, option, value)) return e;
  if (*target < kinematics::kMinLength || *target > kinematics::kMaxLength) {
    const double got = *target;
    target.reset();
    return usage(option, option + " must be between 1e-06 and 1e9 (got " + kinematics::formatNumber(got) + ")");
  }
  return std::nullopt;
}

// X,Y with both finite.
std::optional<Error> point(std::optional<Eigen::Vector2d>& target, const std::string& option,
                           const std::string& value) {
  auto list = parseList(option, value, 2, "X,Y");
  if (!list) return list.error();
  for (const auto& [v, axis] : {std::pair{(*list)[0], "x"}, {(*list)[1], "y"}})
    if (auto e = kinematics::checkCoordinate(v, axis)) return usage(option, option + ": " + e->message);
  target = Eigen::Vector2d((*list)[0], (*list)[1]);
  return std::nullopt;
}

// The options only arm and centres take.
std::optional<Error> applyArmOrCentres(Invocation& inv, const std::string& option, const std::string& value) {
  if (option == "--arm") {
    auto list = parseList(option, value, 2, "UPPER,FOREARM");
    if (!list) return list.error();
    for (const auto& [v, name] : {std::pair{(*list)[0], "upper"}, {(*list)[1], "forearm"}})
      if (auto e = kinematics::checkLength(v, name)) return usage(option, option + ": " + e->message);
    inv.arm = std::pair{(*list)[0], (*list)[1]};
  } else if (option == "--from-point") return point(inv.fromPoint, option, value);
  else if (option == "--to-point") return point(inv.toPoint, option, value);
  else if (option == "--speed") return positive(inv.speed, option, value);
  else if (option == "--step-time") return positive(inv.stepTime, option, value);
  else if (option == "--hole") return drawingLength(inv.holeDiameter, option, value);
  else if (option == "--width") return drawingLength(inv.plateWidth, option, value);
  else if (option == "--elbow") {
    if (value == "up") inv.elbow = kinematics::Branch::Open;
    else if (value == "down") inv.elbow = kinematics::Branch::Crossed;
    else return usage(option, option + " must be 'up' or 'down' (got '" + value + "')");
  } else if (option == "--at") {
    for (const std::string& part : splitCommas(value)) {
      const auto angle = parseNumber(part);
      if (!angle) return usage(option, option + ": '" + part + "' is not a number (expected DEG or DEG,DEG,...)");
      if (!std::isfinite(*angle)) return usage(option, option + " must be finite (got " + part + ")");
      inv.atDeg.push_back(*angle);
    }
  }
  return std::nullopt;
}

// Applies one option and its value to the invocation.
std::optional<Error> apply(Invocation& inv, const std::string& option, const std::string& value) {
  auto number = [&](std::optional<double>& target) -> std::optional<Error> {
    const auto parsed = parseNumber(value);
    if (!parsed) return usage(option, option + ": '" + value + "' is not a number");
    target = *parsed;
    return std::nullopt;
  };
  for (const auto& field : requestFieldsOf(inv.command))
    if (option == kinematics::fieldName(field, kinematics::FrontEnd::Cli)) {
      const auto parsed = parseNumber(value);
      if (!parsed)
        return usage(option, option + ": '" + value + "' is not " +
                                 (field.kind == kinematics::RequestField::Kind::Count ? "a whole number" : "a number"));
      inv.requestValues[field.key] = *parsed;
      return std::nullopt;
    }
  if (option == "--fourbar") {
    auto list = parseList(option, value, 4, "FRAME,CRANK,COUPLER,ROCKER");
    if (!list) return list.error();
    const std::vector<double>& v = *list;
    const kinematics::FourBarLengths lengths{v[0], v[1], v[2], v[3]};
    if (auto e = kinematics::checkFourBarLengths(lengths)) return usage(option, option + ": " + e->message);
    inv.fourBar = lengths;
  } else if (option == "--coupler-point" && inv.command == Command::Cognates && value.find(',') == std::string::npos) {
    if (value.empty()) return usage(option, option + " needs a point's name, or U,V");
    inv.couplerPointName = value;
  } else if (option == "--coupler-point") {
    auto list = parseList(option, value, 2, "U,V (along and across the coupler)");
    if (!list) return list.error();
    inv.couplerPoint = kinematics::CouplerPointSpec{(*list)[0], (*list)[1]};
  } else if (option == "--example") {
    inv.example = value;
  } else if (option == "--unit") {
    if (value.empty() ||
        value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") != std::string::npos)
      return usage(option, option + " must be a unit name made of letters, e.g. mm, m, in (got '" + value + "')");
    inv.lengthUnit = value;
  } else if (option == "--rpm") return number(inv.rpm);
  else if (option == "--omega") return number(inv.omega);
  else if (option == "--alpha") return number(inv.alpha);
  else if (option == "--from") return number(inv.fromDeg);
  else if (option == "--to") return number(inv.toDeg);
  else if (option == "--step") return number(inv.stepDeg);
  else if (option == "--samples") {
    long long n = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc{} || ptr != value.data() + value.size() || value.empty())
      return usage(option, option + ": '" + value + "' is not a whole number");
    inv.samples = n;
  } else if (option == "--branch") {
    if (value == "open") inv.branch = kinematics::Branch::Open;
    else if (value == "crossed") inv.branch = kinematics::Branch::Crossed;
    else return usage(option, option + " must be 'open' or 'crossed' (got '" + value + "')");
  } else if (option == "-o" || option == "--output") {
    if (value.empty()) return usage(option, option + " needs a file name");
    inv.outputFile = value;
  } else if (option == "--format") {
    if (value != "csv" && value != "table")
      return usage(option, option + " must be 'csv' or 'table' (got '" + value + "')");
    inv.tableFormat = value == "table";
  } else if (option == "--json") {
    inv.json = true;
  } else if (option == "--forces") {
    inv.forces = true;
  } else if (option == "--law") {
    if (value != "constant" && value != "ramp" && value != "cycloidal" && value != "345" && value != "table")
      return usage(option, option + " must be constant, ramp, cycloidal, 345 or table (got '" + value + "')");
    inv.law = value;
  } else if (option == "--ramp-time") return positive(inv.rampTime, option, value);
  else if (option == "--rise") return number(inv.riseDeg);
  else if (option == "--duration") return positive(inv.duration, option, value);
  else if (option == "--from-time") return number(inv.fromTime);
  else if (option == "--to-time") return number(inv.toTime);
  else if (option == "--law-table") {
    if (value.empty()) return usage(option, option + " needs a file name");
    inv.lawTable = value;
    if (!inv.law) inv.law = "table";
  } else if (option == "--paper") {
    inv.paper = value;
  } else if (option == "--rates") {
    inv.rates = value;
  } else if (option == "--angles") {
    inv.angles = value;
  } else if (option == "--tolerance" && inv.command == Command::Tolerance) {
    return number(inv.tolerance);
  } else if (option == "--tolerance-of") {
    // "coupler length=0.02,O2 x=0.1": dimension names hold spaces, never a comma or '='.
    std::size_t begin = 0;
    while (begin <= value.size()) {
      const std::size_t end = std::min(value.find(',', begin), value.size());
      const std::string pair = value.substr(begin, end - begin);
      const std::size_t equals = pair.rfind('=');
      double t = 0.0;
      const char* typed = equals == std::string::npos ? nullptr : pair.c_str() + equals + 1;
      char* parsed = nullptr;
      if (typed != nullptr && *typed != '\0') t = std::strtod(typed, &parsed);
      if (typed == nullptr || parsed == nullptr || *parsed != '\0' || equals == 0)
        return usage(option, option + ": '" + pair + "' is not NAME=T (e.g. \"coupler length=0.02\")");
      inv.toleranceOf.emplace_back(pair.substr(0, equals), t);
      begin = end + 1;
    }
  } else if (option == "--objective" || option == "--point" || option == "--path-measure" || option == "--fix-pivots") {
    if (value.empty()) return usage(option, option + " needs a value");
    (option == "--objective"      ? inv.objective
     : option == "--point"        ? inv.objectivePoint
     : option == "--path-measure" ? inv.pathMeasure
                                  : inv.fixPivots) = value;
  } else if (option == "--length-range") {
    if (auto e = positive(inv.lengthRangePercent, option, value)) return e;
    // A percentage so small that it is 0 as a fraction is refused here, as typed, not by the core.
    if (*inv.lengthRangePercent > 95.0 || !(*inv.lengthRangePercent / 100.0 > 0.0))
      return usage(option, option + " must be above 0 and at most 95, a percentage of each length (got " + value + ")");
  } else if (option == "--mc-samples" || option == "--seed" || option == "--evaluations" || option == "--starts") {
    long long n = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    const bool whole = ptr == value.data() + value.size() && !value.empty();
    // optimise's budget and starts are ints in the core: checked here, as typed, before they
    // would wrap (--evaluations 4294968796 ran 1500 designs).
    if ((option == "--evaluations" || option == "--starts") && whole &&
        (ec == std::errc::result_out_of_range || ec == std::errc{})) {
      const bool evaluations = option == "--evaluations";
      const long long lo = evaluations ? kinematics::kMinOptimiseEvaluations : kinematics::kMinOptimiseStarts;
      const long long hi = evaluations ? kinematics::kMaxOptimiseEvaluations : kinematics::kMaxOptimiseStarts;
      if (ec != std::errc{} || n < lo || n > hi)
        return usage(option, option + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                                 " (got " + value + ")");
    }
    if (ec != std::errc{} || !whole) return usage(option, option + ": '" + value + "' is not a whole number");
    if (option == "--seed" && n < 0)
      return usage(option, option + " must be a whole number from 0 (got " + value + ")");
    if (option == "--seed" && inv.command == Command::Optimise && n > 4294967295LL)
      return usage(option, option + " must be a whole number from 0 to 4294967295 (got " + value + ")");
    if (option == "--seed") inv.seed = static_cast<unsigned long long>(n);
    else if (option == "--evaluations") inv.evaluations = n;
    else if (option == "--starts") inv.starts = n;
    else inv.monteCarloSamples = n;
  } else if (option == "--map" || option == "--offset" || option == "--tolerance") {
    return applyCompareOption(inv, option, value);
  } else if (option == "--fraction") return number(inv.reciprocatingFraction);
  else if (option == "--radius") return number(inv.counterweightRadius);
  else if (option == "--spring") {
    if (value.find(',') == std::string::npos)
      return usage(
          option,
          option + " needs two ends, LINK:POINT,LINK:POINT (a ground point alone for the frame; got '" + value + "')");
    inv.springEnds = value;
  } else if (option == "--spring-search") {
    if (value.empty()) return usage(option, option + " needs the name of the link the spring's end goes on");
    inv.springSearchLink = value;
  } else if (option == "--svg") {
    if (value.empty()) return usage(option, option + " needs a file name");
    inv.svgFile = value;
  } else {
    return applyArmOrCentres(inv, option, value);
  }
  return std::nullopt;
}

std::optional<Error> checkArm(const Invocation& inv) {
  if (inv.stepTime && inv.samples) return usage("--samples", "--step-time and --samples cannot be used together");
  if (inv.samples && *inv.samples < 2)
    return usage("--samples", "--samples must be at least 2 for arm (got " + std::to_string(*inv.samples) + ")");
  if (inv.example) return std::nullopt;
  const std::tuple<bool, std::string, std::string> required[] = {{inv.arm.has_value(), "--arm", "UPPER,FOREARM"},
                                                                 {inv.fromPoint.has_value(), "--from-point", "X,Y"},
                                                                 {inv.toPoint.has_value(), "--to-point", "X,Y"},
                                                                 {inv.speed.has_value(), "--speed", "V"}};
  for (const auto& [given, option, shape] : required)
    if (!given)
      return usage(option,
                   "arm needs " + option + " " + shape + ", or --example seed-arm (see linkwright-cli --help arm)");
  return std::nullopt;
}

// A motion law replaces the angle grid and the constant α; each law takes its own options.
std::optional<Error> checkLaw(const Invocation& inv) {
  const bool timeOptions = inv.rampTime || inv.riseDeg || inv.duration || inv.lawTable || inv.fromTime || inv.toTime ||
                           (inv.stepTime && inv.command != Command::Arm);
  if (!inv.law && timeOptions)
    return usage("--law",
                 "the time options (--ramp-time, --rise, --duration, --law-table, --from-time, --to-time, "
                 "--step-time) need --law");
  if (!inv.law) return std::nullopt;
  for (const auto& [given, option] : {std::pair{inv.toDeg.has_value(), "--to"},
                                      {inv.stepDeg.has_value(), "--step"},
                                      {inv.alpha.has_value(), "--alpha"}})
    if (given)
      return usage(option, std::string(option) +
                               " sets the angle grid; with --law the crank follows the law in time "
                               "(use --from-time, --to-time and --samples or --step-time)");
  if (inv.stepTime && inv.samples) return usage("--samples", "--step-time and --samples cannot be used together");
  const std::string& law = *inv.law;
  if (law == "ramp" && !inv.rampTime) return usage("--ramp-time", "--law ramp needs --ramp-time S");
  if ((law == "cycloidal" || law == "345") && (!inv.riseDeg || !inv.duration))
    return usage(inv.riseDeg ? "--duration" : "--rise", "--law " + law + " needs --rise DEG and --duration S");
  if (law == "table" && !inv.lawTable) return usage("--law-table", "--law table needs --law-table FILE.csv");
  if (law != "table" && inv.lawTable) return usage("--law-table", "--law-table goes with --law table");
  return std::nullopt;
}

// dxf draws one pose into one file.
std::optional<Error> checkDxf(const Invocation& inv) {
  if (inv.atDeg.size() > 1)
    return usage("--at", "dxf draws one pose: --at takes one value (got " + std::to_string(inv.atDeg.size()) + ")");
  if (!inv.outputFile) return usage("--output", "dxf needs -o FILE.dxf (where to write the drawing)");
  return std::nullopt;
}

// report draws one pose and writes one file.
std::optional<Error> checkReport(const Invocation& inv) {
  if (inv.atDeg.size() > 1)
    return usage("--at", "report draws one pose: --at takes one value (got " + std::to_string(inv.atDeg.size()) + ")");
  if (!inv.outputFile) return usage("--output", "report needs -o FILE.pdf (where to write the report)");
  return std::nullopt;
}

// balance makes counterweights (--fraction, --radius) or one spring (--spring or
// --spring-search, refused together by the command): a counterweight's option would be
// ignored by a spring balance, so it is refused.
std::optional<Error> checkBalanceOptions(const Invocation& inv) {
  if (auto e = kinematics::checkBalanceRequest(balanceRequestOf(inv))) return usage(e->field, e->message);
  return std::nullopt;
}

// optimise's --point and --path-measure say how a path objective is measured; with another
// objective they would be ignored, so they are refused.
std::optional<Error> checkOptimise(const Invocation& inv) {
  if (inv.objective->rfind("path:", 0) == 0) return std::nullopt;
  for (const auto& [given, option] :
       {std::pair{inv.objectivePoint.has_value(), "--point"}, {inv.pathMeasure.has_value(), "--path-measure"}})
    if (given)
      return usage(option, std::string(option) + " goes with --objective path:TARGETS.csv (got --objective " +
                               *inv.objective + ")");
  return std::nullopt;
}

std::optional<Error> checkCombination(const Invocation& inv) {
  if (inv.command == Command::Arm) return checkArm(inv);
  if (inv.command == Command::Dxf)
    if (auto e = checkDxf(inv)) return e;
  if (inv.command == Command::Report)
    if (auto e = checkReport(inv)) return e;
  if (inv.command == Command::Compare)
    if (auto e = checkCompare(inv)) return e;
  if ((inv.command == Command::Centres || inv.command == Command::Polygon) && inv.atDeg.empty())
    return usage("--at", std::string(commandName(inv.command)) +
                             " needs --at DEG (the crank angle, degrees; repeatable or DEG,DEG,...)");
  if ((inv.command == Command::Machine || inv.command == Command::Balance) && !inv.example && !inv.documentPath)
    return usage("--example", std::string(commandName(inv.command)) +
                                  " needs FILE.json or --example NAME: a linkage with its masses");
  if (inv.command == Command::Balance && !inv.outputFile)
    return usage("--output", "balance needs -o FILE.linkwright (where to write the balanced design)");
  if (inv.command == Command::Tolerance && !inv.tolerance)
    return usage("--tolerance", "tolerance needs --tolerance T (± on every length and pivot, in the length unit)");
  if (inv.command == Command::Tolerance && inv.atDeg.size() > 1)
    return usage("--at", "tolerance lists the sensitivities at one input: --at takes one value (got " +
                             std::to_string(inv.atDeg.size()) + ")");
  if (inv.command == Command::Optimise && !inv.objective)
    return usage("--objective",
                 "optimise needs --objective peak-alpha:LINK, transmission, path:TARGETS.csv or rms-torque");
  if (inv.command == Command::Optimise)
    if (auto e = checkOptimise(inv)) return e;
  if (inv.command == Command::Balance)
    if (auto e = checkBalanceOptions(inv)) return e;
  if (inv.command == Command::Optimise && !inv.example && !inv.documentPath)
    return usage("--example", "optimise needs FILE.json or --example NAME: the linkage to optimise");
  if (inv.command == Command::Optimise && !inv.outputFile)
    return usage("--output", "optimise needs -o FILE.linkwright (where to write the optimised design)");
  if (inv.command == Command::Cognates && !inv.outputFile)
    return usage("--output",
                 "cognates needs -o PREFIX (the cognates are written to PREFIX-1.linkwright and PREFIX-2.linkwright)");
  const bool needsMechanism =
      inv.command == Command::Analyze || inv.command == Command::Classify || inv.command == Command::Extremes ||
      inv.command == Command::Centres || inv.command == Command::Polygon || inv.command == Command::Inversions ||
      inv.command == Command::Dxf || inv.command == Command::Report || inv.command == Command::Compare ||
      inv.command == Command::Machine || inv.command == Command::Cognates || inv.command == Command::Tolerance;
  if (needsMechanism && !inv.fourBar && !inv.example && !inv.documentPath)
    return usage("--fourbar", std::string(commandName(inv.command)) +
                                  " needs FILE.json, --fourbar FRAME,CRANK,COUPLER,ROCKER or --example NAME");
  if (inv.fourBar && inv.example) return usage("--example", "--fourbar and --example cannot be used together");
  if (inv.documentPath && (inv.fourBar || inv.example))
    return usage(inv.fourBar ? "--fourbar" : "--example", std::string(inv.fourBar ? "--fourbar" : "--example") +
                                                              " cannot be used with a document (" + *inv.documentPath +
                                                              ")");
  if (inv.rpm && inv.omega) return usage("--omega", "--rpm and --omega cannot be used together");
  if (inv.stepDeg && inv.samples) return usage("--samples", "--step and --samples cannot be used together");
  return checkLaw(inv);
}

}  // namespace

kinematics::Result<Invocation> parseArguments(const std::vector<std::string>& args) {
  Invocation inv;
  if (args.empty())
    return usage(
        "COMMAND",
        "missing command (analyze, extremes, classify, arm, centres, polygon, inversions, accuracy, dxf, "
        "report, compare, machine, balance, cognates, tolerance, optimise, atlas, synthesize or examples; see --help)");
  const std::string& first = args[0];
  if (first == "--help" || first == "-h" || first == "help") {
    inv.command = Command::Help;
    if (args.size() > 1) inv.helpTopic = args[1];
    return inv;
  }
  if (first == "--version") {
    inv.command = Command::Version;
    return inv;
  }
  if (first == "atlas") {
    // The atlas's options are its own (atlas_options.h).
    bool help = false;
    auto options = parseAtlasArguments(std::vector<std::string>(args.begin() + 1, args.end()), help);
    if (help) {
      inv.helpTopic = "atlas";
      return inv;
    }
    if (!options) return options.error();
    inv.command = Command::Atlas;
    inv.atlas = std::move(options).value();
    return inv;
  }
  if (first == "synthesize") {
    // Each synthesis problem has its own options (synthesize_options.h).
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const std::string& arg : rest)
      if (arg == "--help" || arg == "-h") {
        inv.helpTopic = "synthesize";
        return inv;
      }
    auto request = parseSynthesisArguments(rest);
    if (!request) return request.error();
    inv.command = Command::Synthesize;
    inv.synthesis = std::move(*request);
    return inv;
  }
  if (first == "analyze") inv.command = Command::Analyze;
  else if (first == "classify") inv.command = Command::Classify;
  else if (first == "extremes") inv.command = Command::Extremes;
  else if (first == "examples") inv.command = Command::Examples;
  else if (first == "arm") inv.command = Command::Arm;
  else if (first == "centres") inv.command = Command::Centres;
  else if (first == "polygon") inv.command = Command::Polygon;
  else if (first == "inversions") inv.command = Command::Inversions;
  else if (first == "accuracy") inv.command = Command::Accuracy;
  else if (first == "dxf") inv.command = Command::Dxf;
  else if (first == "report") inv.command = Command::Report;
  else if (first == "compare") inv.command = Command::Compare;
  else if (first == "machine") inv.command = Command::Machine;
  else if (first == "balance") inv.command = Command::Balance;
  else if (first == "cognates") inv.command = Command::Cognates;
  else if (first == "tolerance") inv.command = Command::Tolerance;
  else if (first == "optimise") inv.command = Command::Optimise;
  else if (!first.empty() && first[0] == '-')
    return usage(first, "unknown option '" + first + "' (see linkwright-cli --help)");
  else
    return usage(
        first,
        "unknown command '" + first +
            "' (commands: analyze, extremes, classify, arm, centres, polygon, inversions, accuracy, "
            "dxf, report, compare, machine, balance, cognates, tolerance, optimise, atlas, synthesize, examples; see "
            "--help)");
  if (inv.command == Command::Arm) inv.lengthUnit = "m";  // the arm's seed (004) works in metres

  std::set<std::string> seen;
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string option = args[i];
    std::optional<std::string> inlineValue;
    if (option == "--help" || option == "-h") {
      inv.helpTopic = commandName(inv.command);
      inv.command = Command::Help;
      return inv;
    }
    if (const auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
      inlineValue = option.substr(eq + 1);
      option.resize(eq);
    }
    if (inv.command == Command::Compare && !option.empty() && option[0] != '-' && !inlineValue) {
      if (auto e = takeCompareArgument(inv, option)) return *e;
      continue;
    }
    // A bare argument names a document, for the commands that analyse a linkage.
    const bool takesDocument =
        inv.command == Command::Analyze || inv.command == Command::Extremes || inv.command == Command::Classify ||
        inv.command == Command::Centres || inv.command == Command::Polygon || inv.command == Command::Inversions ||
        inv.command == Command::Dxf || inv.command == Command::Report || inv.command == Command::Machine ||
        inv.command == Command::Balance || inv.command == Command::Cognates || inv.command == Command::Tolerance ||
        inv.command == Command::Optimise;
    if (takesDocument && !option.empty() && option[0] != '-' && !inlineValue) {
      if (inv.documentPath)
        return usage(option, "only one document can be analysed at a time (got '" + *inv.documentPath + "' and '" +
                                 option + "')");
      inv.documentPath = option;
      continue;
    }
    if (!optionsOf(inv.command).count(option)) {
      const std::string what = option.empty() || option[0] != '-' ? "unexpected argument '" : "unknown option '";
      return usage(option, what + option + "' for '" + commandName(inv.command) + "' (see linkwright-cli --help " +
                               commandName(inv.command) + ")");
    }
    const std::string canonical = option == "-o" ? "--output" : option;
    if (canonical != "--at" && !seen.insert(canonical).second)
      return usage(option, option + " is given more than once");
    std::string value;
    if (takesValue(option)) {
      if (inlineValue) value = *inlineValue;
      else if (i + 1 < args.size()) value = args[++i];
      else return usage(option, option + " needs a value");
    } else if (inlineValue) {
      return usage(option, option + " takes no value");
    }
    if (auto e = apply(inv, option, value)) return *e;
  }
  if (auto e = checkCombination(inv)) return *e;
  return inv;
}

kinematics::BalanceRequest balanceRequestOf(const Invocation& inv) {
  kinematics::BalanceRequest r;
  r.fraction = inv.reciprocatingFraction;
  r.radius = inv.counterweightRadius;
  if (inv.springEnds) {
    const auto comma = inv.springEnds->find(',');
    r.spring = std::pair{inv.springEnds->substr(0, comma), inv.springEnds->substr(comma + 1)};
  }
  r.springSearch = inv.springSearchLink;
  r.frontEnd = kinematics::FrontEnd::Cli;
  return r;
}

}  // namespace linkwright::cli
