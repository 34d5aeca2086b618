#include "app/cli/atlas_options.h"

#include "app/cli/option_values.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <charconv>
#include <set>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// A whole number as typed, or a sentence naming the option.
k::Result<long long> wholeNumber(const std::string& option, const std::string& value) {
  long long n = 0;
  const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
  if (ec != std::errc{} || ptr != value.data() + value.size() || value.empty())
    return usage(option, option + ": '" + value + "' is not a whole number");
  return n;
}

std::optional<k::Error> apply(AtlasOptions& o, const std::string& option, const std::string& value) {
  const std::pair<const char*, std::vector<double>*> axes[] = {{"--coupler", &o.axes.coupler},
                                                               {"--rocker", &o.axes.rocker},
                                                               {"--frame", &o.axes.frame},
                                                               {"--along", &o.axes.along},
                                                               {"--across", &o.axes.across}};
  for (const auto& [name, target] : axes)
    if (option == name) {
      auto list = parseList(option, value, 0, "numbers separated by commas");
      if (!list) return list.error();
      *target = std::move(list).value();
      return std::nullopt;
    }
  if (option == "--samples") {
    const auto n = wholeNumber(option, value);
    if (!n) return n.error();
    const auto lo = static_cast<long long>(k::kMinAtlasSamples), hi = static_cast<long long>(k::kMaxAtlasSamples);
    if (*n < lo || *n > hi)
      return usage(option, option + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " +
                               value + ")");
    o.axes.samples = static_cast<std::size_t>(*n);
  } else if (option == "--branch") {
    if (value == "open") o.axes.branch = k::Branch::Open;
    else if (value == "crossed") o.axes.branch = k::Branch::Crossed;
    else return usage(option, option + " must be 'open' or 'crossed' (got '" + value + "')");
  } else if (option == "--filter") {
    auto filter = k::parseAtlasFilter(value, option);
    if (!filter) return filter.error();
    o.filter = *filter;
  } else if (option == "--cell") {
    const auto n = wholeNumber(option, value);
    if (!n) return n.error();
    if (*n < 0) return usage(option, option + " must be a cell number from 0 (got " + value + ")");
    o.cell = static_cast<std::size_t>(*n);
  } else if (option == "--crank") {
    const auto v = parseNumber(value);
    if (!v) return usage(option, option + ": '" + value + "' is not a number");
    if (auto e = k::checkLength(*v, option, "length")) return usage(option, e->message);
    o.crank = *v;
  } else if (option == "--unit") {
    if (value.empty() ||
        value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") != std::string::npos)
      return usage(option, option + " must be a unit name made of letters, e.g. mm, m, in (got '" + value + "')");
    o.lengthUnit = value;
  } else if (option == "-o" || option == "--output") {
    if (value.empty()) return usage(option, option + " needs a file name");
    o.outputFile = value;
  }
  return std::nullopt;
}

}  // namespace

k::Result<AtlasOptions> parseAtlasArguments(const std::vector<std::string>& args, bool& help) {
  static const std::set<std::string> known{"--coupler", "--rocker", "--frame",  "--along", "--across",
                                           "--samples", "--branch", "--filter", "--json",  "--cell",
                                           "--crank",   "--unit",   "-o",       "--output"};
  AtlasOptions o;
  std::set<std::string> seen;
  help = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string option = args[i];
    if (option == "--help" || option == "-h") {
      help = true;
      return o;
    }
    std::optional<std::string> inlineValue;
    if (const auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
      inlineValue = option.substr(eq + 1);
      option.resize(eq);
    }
    if (!known.count(option)) {
      const std::string what = option.empty() || option[0] != '-' ? "unexpected argument '" : "unknown option '";
      return usage(option, what + option + "' for 'atlas' (see linkwright-cli --help atlas)");
    }
    if (!seen.insert(option == "-o" ? "--output" : option).second)
      return usage(option, option + " is given more than once");
    if (option == "--json") {
      if (inlineValue) return usage(option, option + " takes no value");
      o.json = true;
      continue;
    }
    std::string value;
    if (inlineValue) value = *inlineValue;
    else if (i + 1 < args.size()) value = args[++i];
    else return usage(option, option + " needs a value");
    if (auto e = apply(o, option, value)) return *e;
  }
  if (auto e = k::checkAtlasAxes(o.axes)) return usage("--" + e->field, "--" + e->message);
  if (const std::size_t cells = k::atlasCellCount(o.axes); !o.cell && cells > k::kMaxAtlasRunCells)
    return usage("--coupler", "--coupler × --rocker × --frame × --along × --across is " +
                                  std::to_string(o.axes.coupler.size()) + " × " + std::to_string(o.axes.rocker.size()) +
                                  " × " + std::to_string(o.axes.frame.size()) + " × " +
                                  std::to_string(o.axes.along.size()) + " × " + std::to_string(o.axes.across.size()) +
                                  " = " + std::to_string(cells) + " cells; atlas computes at most " +
                                  std::to_string(k::kMaxAtlasRunCells) + " in one run: give fewer values");
  if (o.cell) {
    const std::size_t count = k::atlasCellCount(o.axes);
    if (*o.cell >= count)
      return usage("--cell", "--cell must be between 0 and " + std::to_string(count - 1) + ", the grid's cells (got " +
                                 std::to_string(*o.cell) + ")");
    if (!o.outputFile) return usage("--output", "--cell needs -o FILE.linkwright (where to write the cell's design)");
    if (o.json || seen.count("--filter"))
      return usage(o.json ? "--json" : "--filter",
                   std::string(o.json ? "--json" : "--filter") + " goes with the table, not with --cell");
  } else if (seen.count("--crank") || seen.count("--unit")) {
    const std::string option = seen.count("--crank") ? "--crank" : "--unit";
    return usage(option, option + " sets the design --cell writes; give --cell I too");
  }
  return o;
}

}  // namespace linkwright::cli
