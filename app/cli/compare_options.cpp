#include "app/cli/compare_options.h"
#include "app/cli/option_values.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::compare::OffsetMode;

constexpr const char* kShape =
    "linkwright-cli compare FILE.json|--example NAME|--fourbar F,C,C,R TABLE.csv --map "
    "COLUMN=WHAT[:UNIT][:FLAG],...|auto (see linkwright-cli --help compare)";

std::optional<Error> parseOffset(Invocation& inv, const std::string& value) {
  if (value == "auto" || value == "none") {
    inv.compareOffset = CompareOffsetOption{value == "auto" ? OffsetMode::Auto : OffsetMode::None, 0.0};
    return std::nullopt;
  }
  const auto degrees = parseNumber(value);
  if (!degrees)
    return usage("--offset", "--offset must be auto, none or a crank angle in degrees (got '" + value + "')");
  if (!(std::abs(*degrees) <= 5.0))
    return usage("--offset", "--offset must be within ±5 degrees (got " + kinematics::formatNumber(*degrees) + ")");
  inv.compareOffset = CompareOffsetOption{OffsetMode::Given, *degrees};
  return std::nullopt;
}

std::optional<Error> parseTolerance(Invocation& inv, const std::string& value) {
  const std::vector<std::string> parts = splitCommas(value);
  std::string percent = parts[0];
  if (!percent.empty() && percent.back() == '%') percent.pop_back();
  const auto pct = parseNumber(percent);
  const auto abs = parts.size() == 2 ? parseNumber(parts[1]) : std::optional<double>(0.0);
  if (parts.size() > 2 || !pct || !abs)
    return usage("--tolerance",
                 "--tolerance must be PCT[,ABS]: a percent of each column's span, optionally an "
                 "absolute part in each column's unit (got '" +
                     value + "')");
  if (!(*pct >= 0.0 && *pct <= 100.0))
    return usage("--tolerance",
                 "--tolerance: the percent must be between 0 and 100 (got " + kinematics::formatNumber(*pct) + ")");
  if (!(std::isfinite(*abs) && *abs >= 0.0))
    return usage("--tolerance", "--tolerance: the absolute part must be zero or positive and finite (got " +
                                    kinematics::formatNumber(*abs) + ")");
  inv.compareTolerance = CompareToleranceOption{*pct, parts.size() == 2 ? std::optional<double>(*abs) : std::nullopt};
  return std::nullopt;
}

}  // namespace

std::optional<Error> applyCompareOption(Invocation& inv, const std::string& option, const std::string& value) {
  if (option == "--map") {
    if (value.empty())
      return usage(option, "--map needs the column mapping, e.g. 1=crank-angle:deg,2=coupler_angle:deg");
    inv.compareMap = value;
  } else if (option == "--offset") return parseOffset(inv, value);
  else if (option == "--tolerance") return parseTolerance(inv, value);
  return std::nullopt;
}

std::optional<Error> takeCompareArgument(Invocation& inv, const std::string& argument) {
  if (inv.documentPath)
    return usage(argument, "compare takes a document and one table (got '" + *inv.documentPath + "', '" +
                               *inv.compareTable + "' and '" + argument + "')");
  if (inv.compareTable) inv.documentPath = *inv.compareTable;
  inv.compareTable = argument;
  return std::nullopt;
}

std::optional<Error> checkCompare(const Invocation& inv) {
  if (!inv.compareTable) return usage("TABLE.csv", std::string("compare needs the other tool's table: ") + kShape);
  if (!inv.compareMap) return usage("--map", std::string("compare needs --map: ") + kShape);
  return std::nullopt;
}

}  // namespace linkwright::cli
