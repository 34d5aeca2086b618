#include "app/cli/compare_report.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
namespace kc = kinematics::compare;
using k::formatShort;

using Rows = std::vector<std::vector<std::string>>;

// Left-aligned columns two spaces apart, each line indented by `indent`.
void writeAligned(std::ostream& out, const Rows& rows, const std::string& indent = "") {
  std::vector<std::size_t> width;
  const auto length = [](const std::string& s) {  // UTF-8 code points, for "°" and "²"
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (width.size() <= i) width.push_back(0);
      width[i] = std::max(width[i], length(row[i]));
    }
  for (const auto& row : rows) {
    std::string line = indent;
    for (std::size_t i = 0; i < row.size(); ++i)
      line += row[i] + (i + 1 < row.size() ? std::string(width[i] - length(row[i]) + 2, ' ') : "");
    out << line << "\n";
  }
}

std::string delimiterName(const k::io::NumericTable& t) {
  const std::string d = t.delimiter == '\t'  ? "tab-separated"
                        : t.delimiter == ';' ? "';'-separated"
                                             : "comma-separated";
  return d + (t.decimalComma ? ", decimal comma" : "");
}

std::string headerOf(const k::io::NumericTable& t, std::size_t column) {
  std::string label = t.labels[column];
  if (label.size() > 28) label = label.substr(0, 25) + "...";
  return label.empty() ? "-" : label;
}

std::string xDescription(const CompareContext& c, const kc::Comparison& cmp) {
  const kc::AxisColumn& axis = cmp.axis;
  std::string text = "column " + std::to_string(axis.column + 1) + " (" + headerOf(c.table, axis.column) + "), ";
  if (axis.kind == kc::AxisKind::CrankAngle)
    return text + "the crank angle in " + axis.unit.name + "; the crank at " +
           formatShort(k::radPerSecToRpm(c.drive.omega)) + " rpm";
  text += "the time in " + axis.unit.name;
  if (c.drive.law) return text + "; the crank follows the linkage's motion law";
  return text + "; the crank at " + formatShort(k::radPerSecToRpm(c.drive.omega)) + " rpm from " +
         formatShort(k::radToDeg(c.drive.startAngle)) + "° at t = 0";
}

std::string solvedAt(double offsetDeg) {
  return std::string("rows solved at their crank angle ") + (offsetDeg < 0.0 ? "- " : "+ ") +
         formatShort(std::abs(offsetDeg), 4) + "°";
}

// "line 8 (column 3), lines 5, 17 (column 4)": the cells the offset fit left out.
std::string leftOutOfFit(const kc::Comparison& cmp) {
  std::string text;
  for (const kc::ColumnComparison& column : cmp.columns) {
    std::vector<std::string> lines;
    for (const kc::RowComparison& row : column.rows)
      if (row.outsideFit) lines.push_back(std::to_string(row.line));
    if (lines.empty()) continue;
    // A long table's misfit rows are named a few at a time; the flagged rows below list them all.
    constexpr std::size_t kNamed = 20;
    std::string entry = lines.size() == 1 ? "line " : "lines ";
    for (std::size_t i = 0; i < std::min(lines.size(), kNamed); ++i) entry += (i ? ", " : "") + lines[i];
    if (lines.size() > kNamed) entry += " and " + std::to_string(lines.size() - kNamed) + " more";
    text += (text.empty() ? "" : "; ") + entry + " (column " + std::to_string(column.mapped.column + 1) + ")";
  }
  return text;
}

std::string offsetDescription(const CompareContext& c, const kc::Comparison& cmp) {
  const std::string value = formatShort(cmp.offsetDeg, 4) + "°";
  switch (cmp.offsetMode) {
  case kc::OffsetMode::None: return "none (rows solved at the crank angle they state)";
  case kc::OffsetMode::Given: return value + " (given): " + solvedAt(cmp.offsetDeg);
  case kc::OffsetMode::Auto: break;
  }
  std::string text = value + " (fitted within ±" + formatShort(c.options.offsetBoundDeg) + "° to " +
                     (cmp.offsetFromPositions ? "the position columns" : "all columns") +
                     ", leaving out cells beyond 3 tolerances): " + solvedAt(cmp.offsetDeg);
  if (cmp.offsetKeptZero) text += "\n        zero kept: no offset halves the misfit of the rows that agree";
  if (cmp.offsetAtBound) text += "\n        at the bound: the table may be shifted further, or mapped wrong";
  if (const std::string left = leftOutOfFit(cmp); !left.empty()) text += "\n        left out of the fit: " + left;
  return text;
}

void writeFlagged(std::ostream& out, const kc::Comparison& cmp) {
  for (const kc::ColumnComparison& column : cmp.columns) {
    if (column.flagged == 0) continue;
    out << "\ncolumn " << column.mapped.column + 1 << ", " << column.mapped.describe() << ": " << column.flagged
        << " of " << column.compared << " rows beyond ±" << formatShort(column.tolerance, 3) << "\n";
    Rows rows{{"line", "x", "crank (deg)", "value", "exact", "deviation"}};
    for (const kc::RowComparison& row : column.rows) {
      if (!row.flagged) continue;
      rows.push_back({std::to_string(row.line), formatShort(row.x), formatShort(row.inputDeg, 7),
                      formatShort(row.value), row.exact ? formatShort(*row.exact, 6) : "none",
                      row.exact ? formatShort(row.deviation, 4) : row.note});
    }
    writeAligned(out, rows, "  ");
  }
}

}  // namespace

void writeComparisonText(std::ostream& out, const CompareContext& c, const kc::Comparison& cmp) {
  out << "table:     " << c.tablePath << ", " << c.table.rows.size() << " rows, " << delimiterName(c.table) << "\n"
      << "exact:     " << c.source << "\n"
      << "x:         " << xDescription(c, cmp) << "\n"
      << "offset:    " << offsetDescription(c, cmp) << "\n"
      << "tolerance: "
      << (c.options.absoluteTolerance ? formatShort(*c.options.absoluteTolerance)
                                      : std::string("each column's rounding"))
      << " + " << formatShort(c.options.relativeTolerance * 100.0) << " % of its span (max - min of the exact values)\n"
      << "map:       " << kc::formatColumnMap(c.mapping) << "\n\n";
  Rows rows{{"column", "header", "compared with", "rows", "worst", "at x", "rms", "tolerance", "flagged"}};
  for (const kc::ColumnComparison& column : cmp.columns)
    rows.push_back({std::to_string(column.mapped.column + 1), headerOf(c.table, column.mapped.column),
                    column.mapped.describe(), std::to_string(column.compared), formatShort(column.worst, 4),
                    formatShort(column.worstX), formatShort(column.rms, 4), formatShort(column.tolerance, 3),
                    std::to_string(column.flagged)});
  writeAligned(out, rows);
  const std::size_t flagged = cmp.flaggedRows();
  if (flagged == 0) out << "\nevery row agrees within the tolerance\n";
  else writeFlagged(out, cmp);
}

void writeComparisonJson(std::ostream& out, const CompareContext& c, const kc::Comparison& cmp,
                         const std::function<void(std::size_t done, std::size_t total)>& progress) {
  using nlohmann::json;
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  // The document without its rows is small: it is laid out whole, and each column's rows are
  // written into it one object at a time, as dump(2) would place them (8 spaces in, "]" at 6).
  // A table of 10⁶ rows is then never a tree of 10⁶ JSON objects.
  json columns = json::array();
  for (const kc::ColumnComparison& column : cmp.columns)
    columns.push_back({{"column", column.mapped.column + 1},
                       {"header", c.table.labels[column.mapped.column]},
                       {"quantity", column.mapped.quantity.key},
                       {"unit", column.mapped.unit.name},
                       {"negated", column.mapped.negated},
                       {"magnitude", column.mapped.magnitude},
                       {"reversed", column.mapped.reversed},
                       {"span", number(column.span)},
                       {"tolerance", number(column.tolerance)},
                       {"worst", number(column.worst)},
                       {"worst_at_x", number(column.worstX)},
                       {"rms", number(column.rms)},
                       {"compared", column.compared},
                       {"flagged", column.flagged},
                       {"rows", json::array()}});
  const char* mode = cmp.offsetMode == kc::OffsetMode::Auto   ? "auto"
                     : cmp.offsetMode == kc::OffsetMode::None ? "none"
                                                              : "given";
  const json doc{{"table", c.tablePath},
                 {"rows", c.table.rows.size()},
                 {"map", kc::formatColumnMap(c.mapping)},
                 {"offset",
                  {{"mode", mode},
                   {"deg", number(cmp.offsetDeg)},
                   {"at_bound", cmp.offsetAtBound},
                   {"kept_zero", cmp.offsetKeptZero}}},
                 {"tolerance_percent_of_span", number(c.options.relativeTolerance * 100.0)},
                 {"flagged_rows", cmp.flaggedRows()},
                 {"columns", std::move(columns)}};
  // The table's headers and its path are the file's own bytes, not always UTF-8: nlohmann would
  // throw (type_error 316) and end the program; invalid bytes become U+FFFD, as jsonQuote does.
  const std::string skeleton = doc.dump(2, ' ', false, json::error_handler_t::replace);
  // Each column's empty "rows" array, in order (a string's quotes are escaped, so only these match).
  const std::string empty = "\"rows\": []";
  std::size_t at = 0;
  std::string indented;
  std::size_t total = 0, written = 0;
  for (const kc::ColumnComparison& column : cmp.columns) total += column.rows.size();
  for (const kc::ColumnComparison& column : cmp.columns) {
    const std::size_t found = skeleton.find(empty, at);
    out.write(skeleton.data() + at, static_cast<std::streamsize>(found - at));
    out << "\"rows\": [";
    for (std::size_t r = 0; r < column.rows.size(); ++r) {
      const kc::RowComparison& row = column.rows[r];
      const json object{{"line", row.line},
                        {"x", number(row.x)},
                        {"crank_angle_deg", number(row.inputDeg)},
                        {"value", number(row.value)},
                        {"exact", row.exact ? number(*row.exact) : json(nullptr)},
                        {"deviation", row.exact ? number(row.deviation) : json(nullptr)},
                        {"flagged", row.flagged},
                        {"outside_fit", row.outsideFit},
                        {"note", row.note}};
      const std::string text = object.dump(2, ' ', false, json::error_handler_t::replace);
      indented.assign(r ? ",\n        " : "\n        ");
      for (const char ch : text) {
        indented += ch;
        if (ch == '\n') indented += "        ";
      }
      out << indented;
      if (progress && ++written % 4096 == 0) progress(written, total);
    }
    out << (column.rows.empty() ? "]" : "\n      ]");
    at = found + empty.size();
  }
  out.write(skeleton.data() + at, static_cast<std::streamsize>(skeleton.size() - at));
  out << "\n";
}

}  // namespace linkwright::cli
