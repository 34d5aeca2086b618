#include "app/cli/synthesize_options.h"
#include "app/cli/option_values.h"

#include "kinematics/model/number_text.h"
#include "kinematics/synthesis/named_function.h"

#include "kinematics/model/validate.h"
#include "kinematics/synthesis/time_ratio.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::formatNumber;

// Finite numbers within the input domain, comma-separated; `count` 0 means any number of them.
kinematics::Result<std::vector<double>> parseCoordinates(const std::string& option, const std::string& text,
                                                         std::size_t count, const std::string& shape) {
  auto values = parseList(option, text, count, shape);
  if (!values) return values.error();
  for (const double value : *values)
    if (auto e = kinematics::checkCoordinate(value, option)) return usage(option, e->message);
  return values;
}

kinematics::Result<double> finiteNumber(const std::string& option, const std::string& text) {
  auto list = parseCoordinates(option, text, 1, "a number");
  if (!list) return list.error();
  return list->front();
}

kinematics::Result<long long> wholeNumber(const std::string& option, const std::string& text, long long lo,
                                          long long hi) {
  long long n = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc{} || ptr != text.data() + text.size() || text.empty())
    return usage(option, option + ": '" + text + "' is not a whole number");
  if (n < lo || n > hi)
    return usage(option, option + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " +
                             text + ")");
  return n;
}

// The option's handler: reads the value into the request, or says why it cannot.
using Handler = std::function<std::optional<Error>(SynthesisRequest&, const std::string& option, const std::string&)>;

Handler length(std::optional<double> SynthesisRequest::*field) {
  return [field](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
    auto v = finiteNumber(option, value);
    if (!v) return v.error();
    if (auto e = kinematics::checkLength(*v, option)) return usage(option, e->message);
    r.*field = *v;
    return std::nullopt;
  };
}

Handler coordinate(std::optional<double> SynthesisRequest::*field) {
  return [field](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
    auto v = finiteNumber(option, value);
    if (!v) return v.error();
    r.*field = *v;
    return std::nullopt;
  };
}

// An angle span in degrees: nonzero, less than a turn either way.
Handler span(std::optional<double> SynthesisRequest::*field) {
  return [field](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
    auto v = finiteNumber(option, value);
    if (!v) return v.error();
    if (*v == 0.0 || std::abs(*v) >= 360.0)
      return usage(option, option + " must be nonzero and between -360 and 360 degrees, both excluded (got " +
                               formatNumber(*v) + ")");
    r.*field = *v;
    return std::nullopt;
  };
}

std::optional<Error> timeRatio(SynthesisRequest& r, const std::string& option, const std::string& value) {
  auto v = finiteNumber(option, value);
  if (!v) return v.error();
  if (!(*v >= 1.0 && *v <= kinematics::kMaxTimeRatio))
    return usage(option, option + " must be between 1 and " + formatNumber(kinematics::kMaxTimeRatio) +
                             " (slow stroke / quick stroke; got " + formatNumber(*v) + ")");
  r.timeRatio = *v;
  return std::nullopt;
}

std::optional<Error> swing(SynthesisRequest& r, const std::string& option, const std::string& value) {
  auto v = finiteNumber(option, value);
  if (!v) return v.error();
  if (!(*v > 0.0 && *v < 180.0))
    return usage(option, option + " must be between 0 and 180 degrees, both excluded (got " + formatNumber(*v) + ")");
  r.swingDeg = *v;
  return std::nullopt;
}

std::optional<Error> point(std::vector<Eigen::Vector2d>& into, const std::string& option, const std::string& value) {
  auto list = parseCoordinates(option, value, 2, "X,Y");
  if (!list) return list.error();
  into.emplace_back((*list)[0], (*list)[1]);
  return std::nullopt;
}

const std::map<std::string, Handler>& handlers() {
  static const std::map<std::string, Handler> table{
      {"--unit",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         if (value.empty() ||
             value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") != std::string::npos)
           return usage(option, option + " must be a unit name made of letters, e.g. mm, m, in (got '" + value + "')");
         r.lengthUnit = value;
         return std::nullopt;
       }},
      {"--min-transmission",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto v = finiteNumber(option, value);
         if (!v) return v.error();
         if (!(*v >= 0.0 && *v <= 90.0))
           return usage(option, option + " must be between 0 and 90 degrees (got " + formatNumber(*v) + ")");
         r.minTransmissionDeg = *v;
         return std::nullopt;
       }},
      {"--max-link", length(&SynthesisRequest::maxLink)},
      {"--max-ratio",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto v = finiteNumber(option, value);
         if (!v) return v.error();
         if (!(*v >= 1.0 && *v <= kinematics::kMaxLengthRatio))
           return usage(option,
                        option + " must be between 1 and 1e6 (longest / shortest link; got " + formatNumber(*v) + ")");
         r.maxLinkRatio = *v;
         return std::nullopt;
       }},
      {"--json",
       [](SynthesisRequest& r, const std::string&, const std::string&) -> std::optional<Error> {
         r.json = true;
         return std::nullopt;
       }},
      {"--choose",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto n = wholeNumber(option, value, 1, 1000000);
         if (!n) return n.error();
         r.choose = *n;
         return std::nullopt;
       }},
      {"--output",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         if (value.empty()) return usage(option, option + " needs a file name");
         r.outputFile = value;
         return std::nullopt;
       }},
      {"--swing", swing},
      {"--time-ratio", timeRatio},
      {"--rocker", length(&SynthesisRequest::rocker)},
      {"--frame", length(&SynthesisRequest::frame)},
      {"--count",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto n = wholeNumber(option, value, 1, 1000);
         if (!n) return n.error();
         r.count = *n;
         return std::nullopt;
       }},
      {"--stroke", length(&SynthesisRequest::stroke)},
      {"--rod", length(&SynthesisRequest::rod)},
      {"--offset", coordinate(&SynthesisRequest::offset)},
      {"--crank", length(&SynthesisRequest::crank)},
      {"--link", length(&SynthesisRequest::link)},
      {"--guide-height", coordinate(&SynthesisRequest::guideHeight)},
      {"--function",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         if (kinematics::findNamedFunction(value) != nullptr) {
           r.function = value;
           return std::nullopt;
         }
         std::string names;
         for (const kinematics::NamedFunction& f : kinematics::namedFunctions())
           names += (names.empty() ? "" : ", ") + std::string(f.name);
         return usage(option, option + " must be one of " + names + " (got '" + value + "')");
       }},
      {"--x0", coordinate(&SynthesisRequest::x0)},
      {"--x1", coordinate(&SynthesisRequest::x1)},
      {"--input-start", coordinate(&SynthesisRequest::inputStartDeg)},
      {"--input-span", span(&SynthesisRequest::inputSpanDeg)},
      {"--output-start", coordinate(&SynthesisRequest::outputStartDeg)},
      {"--output-span", span(&SynthesisRequest::outputSpanDeg)},
      {"--points",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto n = wholeNumber(option, value, 3, 1000);
         if (!n) return n.error();
         r.points = *n;
         return std::nullopt;
       }},
      {"--at",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto list = parseCoordinates(option, value, 0, "X1,X2,X3,...");
         if (!list) return list.error();
         r.at.insert(r.at.end(), list->begin(), list->end());
         return std::nullopt;
       }},
      {"--pose",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto list = parseCoordinates(option, value, 3, "X,Y,DEG");
         if (!list) return list.error();
         r.poses.push_back({Eigen::Vector2d((*list)[0], (*list)[1]), (*list)[2]});
         return std::nullopt;
       }},
      {"--circle-point", [](SynthesisRequest& r, const std::string& option,
                            const std::string& value) { return point(r.circlePoints, option, value); }},
      {"--centre",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto v = finiteNumber(option, value);
         if (!v) return v.error();
         r.centres.push_back(*v);
         return std::nullopt;
       }},
      {"--full-turn",
       [](SynthesisRequest& r, const std::string&, const std::string&) -> std::optional<Error> {
         r.fullTurn = true;
         return std::nullopt;
       }},
      {"--target", [](SynthesisRequest& r, const std::string& option,
                      const std::string& value) { return point(r.targets, option, value); }},
      {"--timing",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto list = parseCoordinates(option, value, 0, "DEG,DEG,...");
         if (!list) return list.error();
         r.timingDeg = *list;
         return std::nullopt;
       }},
      {"--timing-from",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         if (value != "start" && value != "frame")
           return usage(option, option + " must be 'start' or 'frame' (got '" + value + "')");
         r.timingFromFrame = value == "frame";
         return std::nullopt;
       }},
      {"--starts",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         // Parsed whole first, so that the message for too many can say where more are run.
         auto n =
             wholeNumber(option, value, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max());
         if (!n) return n.error();
         if (*n < 1 || *n > kMaxCliPathStarts)
           return usage(option, option + " must be between 1 and " + std::to_string(kMaxCliPathStarts) + " (got " +
                                    value + ")" +
                                    (*n > kMaxCliPathStarts ? "; a longer search runs in the designer's Synthesis "
                                                              "panel, where it can be cancelled"
                                                            : ""));
         r.starts = *n;
         return std::nullopt;
       }},
      {"--seed",
       [](SynthesisRequest& r, const std::string& option, const std::string& value) -> std::optional<Error> {
         auto n = wholeNumber(option, value, 0, 4294967295LL);
         if (!n) return n.error();
         r.seed = *n;
         return std::nullopt;
       }},
  };
  return table;
}

const std::set<std::string>& optionsOf(SynthesisProblem problem) {
  static const std::set<std::string> swing{"--swing", "--time-ratio", "--rocker", "--frame", "--count"};
  static const std::set<std::string> slider{"--stroke", "--time-ratio", "--rod", "--offset"};
  static const std::set<std::string> shaper{"--stroke", "--time-ratio", "--crank", "--link", "--guide-height"};
  static const std::set<std::string> function{
      "--function",     "--x0",    "--x1",          "--input-start", "--input-span",
      "--output-start", "--frame", "--output-span", "--points",      "--at"};
  static const std::set<std::string> motion{"--pose", "--circle-point", "--centre", "--full-turn"};
  static const std::set<std::string> path{"--target", "--timing", "--timing-from", "--starts", "--seed", "--full-turn"};
  switch (problem) {
  case SynthesisProblem::Swing: return swing;
  case SynthesisProblem::Slider: return slider;
  case SynthesisProblem::Shaper: return shaper;
  case SynthesisProblem::Function: return function;
  case SynthesisProblem::Motion: return motion;
  case SynthesisProblem::Path: return path;
  }
  return swing;
}

bool isCommon(const std::string& option) {
  static const std::set<std::string> common{"--unit", "--min-transmission", "--max-link", "--max-ratio",
                                            "--json", "--choose",           "--output"};
  return common.count(option) > 0;
}

bool repeatable(const std::string& option) {
  return option == "--pose" || option == "--circle-point" || option == "--centre" || option == "--target" ||
         option == "--at";
}

bool takesValue(const std::string& option) { return option != "--json" && option != "--full-turn"; }

}  // namespace

kinematics::Result<SynthesisRequest> parseSynthesisArguments(const std::vector<std::string>& args) {
  SynthesisRequest r;
  const std::string problems = "swing, slider, shaper, function, motion or path";
  if (args.empty()) return usage("PROBLEM", "synthesize needs a problem: " + problems + " (see --help synthesize)");
  bool known = false;
  for (const SynthesisProblem p : {SynthesisProblem::Swing, SynthesisProblem::Slider, SynthesisProblem::Shaper,
                                   SynthesisProblem::Function, SynthesisProblem::Motion, SynthesisProblem::Path})
    if (args[0] == problemName(p)) {
      r.problem = p;
      known = true;
    }
  if (!known) return usage("PROBLEM", "unknown synthesis problem '" + args[0] + "' (problems: " + problems + ")");
  const std::string name = std::string("synthesize ") + problemName(r.problem);
  std::set<std::string> seen;
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string option = args[i];
    std::optional<std::string> inlineValue;
    if (const auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
      inlineValue = option.substr(eq + 1);
      option.resize(eq);
    }
    const std::string typed = option;
    if (option == "-o") option = "--output";
    if (!isCommon(option) && !optionsOf(r.problem).count(option)) {
      const std::string what = option.empty() || option[0] != '-' ? "unexpected argument '" : "unknown option '";
      return usage(typed, what + typed + "' for '" + name + "' (see linkwright-cli --help synthesize)");
    }
    if (!repeatable(option) && !seen.insert(option).second) return usage(typed, typed + " is given more than once");
    std::string value;
    if (takesValue(option)) {
      if (inlineValue) value = *inlineValue;
      else if (i + 1 < args.size()) value = args[++i];
      else return usage(typed, typed + " needs a value");
    } else if (inlineValue) {
      return usage(typed, typed + " takes no value");
    }
    if (auto e = handlers().at(option)(r, typed, value)) return *e;
  }
  if (auto e = checkSynthesisRequest(r)) return *e;
  return r;
}

}  // namespace linkwright::cli
