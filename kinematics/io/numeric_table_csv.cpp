#include "kinematics/io/numeric_table_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace linkwright::kinematics::io {
namespace {

std::string_view trimmed(std::string_view cell) {
  while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ' || cell.back() == '\t')) cell.remove_suffix(1);
  while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
  return cell;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.push_back(text.substr(0, end));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
  }
  return lines;
}

// Tabs win (spreadsheets copy as tab-separated text), then ';' (European Excel), then ','.
char detectDelimiter(const std::vector<std::string_view>& lines) {
  bool semicolon = false;
  for (std::size_t i = 0; i < std::min<std::size_t>(lines.size(), 50); ++i) {
    if (lines[i].find('\t') != std::string_view::npos) return '\t';
    semicolon = semicolon || lines[i].find(';') != std::string_view::npos;
  }
  return semicolon ? ';' : ',';
}

// The cells of one line, with RFC 4180 quotes removed ("Angle, deg" stays one cell).
std::vector<std::string> splitCells(std::string_view line, char delimiter) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
      else quoted = !quoted;
    } else if (c == delimiter && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  for (std::string& cell : cells) cell = std::string(trimmed(cell));
  while (cells.size() > 1 && cells.back().empty()) cells.pop_back();
  return cells;
}

// A number and half a unit in its last printed digit ("33,28" → 0.005; "1.5e-3" → 5e-5).
struct Cell {
  double value = 0.0;
  double rounding = 0.5;
};

std::optional<Cell> parseNumber(std::string cell, bool decimalComma) {
  if (decimalComma) std::replace(cell.begin(), cell.end(), ',', '.');
  if (!cell.empty() && cell.front() == '+') cell.erase(0, 1);
  Cell parsed;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), parsed.value);
  if (ec != std::errc{} || end != cell.data() + cell.size() || cell.empty() || !std::isfinite(parsed.value))
    return std::nullopt;
  const std::size_t exponentAt = cell.find_first_of("eE");
  const std::string mantissa = cell.substr(0, exponentAt);
  const std::size_t point = mantissa.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
  long exponent = 0;
  if (exponentAt != std::string::npos) {
    const char* from = cell.c_str() + exponentAt + 1;
    if (*from == '+') ++from;
    std::from_chars(from, cell.c_str() + cell.size(), exponent);  // from_chars took the whole cell above
  }
  parsed.rounding = 0.5 * std::pow(10.0, static_cast<double>(exponent - decimals));
  // "0e400" is zero to half of 1e400: a precision no double holds, not a measurement.
  if (!std::isfinite(parsed.rounding)) return std::nullopt;
  return parsed;
}

struct ParsedLine {
  bool numeric = false;
  NumericRow row;
  std::vector<double> rounding;
};

ParsedLine parseLine(const std::vector<std::string>& cells, bool decimalComma, int line) {
  ParsedLine parsed;
  parsed.row.line = line;
  bool any = false;
  for (const std::string& cell : cells) {
    if (cell.empty()) {
      parsed.row.cells.emplace_back();
      parsed.rounding.push_back(0.0);
      continue;
    }
    const auto number = parseNumber(cell, decimalComma);
    if (!number) return {};
    parsed.row.cells.emplace_back(number->value);
    parsed.rounding.push_back(number->rounding);
    any = true;
  }
  parsed.numeric = any;
  return parsed;
}

Error csvError(const std::string& why) { return Error{ErrorCode::InvalidValue, "csv", why}; }

void addLabels(std::vector<std::string>& labels, const std::vector<std::string>& cells) {
  if (labels.size() < cells.size()) labels.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (!cells[c].empty()) labels[c] += (labels[c].empty() ? "" : " ") + cells[c];
}

}  // namespace

Result<NumericTable> readNumericTable(std::string_view text) {
  if (text.size() > kMaxNumericTableBytes) return csvError("the table is larger than 64 MiB");
  // A UTF-8 byte-order mark (Excel writes one) is not part of the first line: with it, a
  // headerless table's first row read as its header.
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  const std::vector<std::string_view> lines = splitLines(text);
  NumericTable table;
  table.delimiter = detectDelimiter(lines);
  table.decimalComma = table.delimiter != ',';
  std::vector<std::string> labels;
  std::vector<double> rounding;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int lineNumber = static_cast<int>(i) + 1;
    std::string_view line = lines[i];
    if (line.ends_with('\r')) line.remove_suffix(1);
    const std::string_view content = trimmed(line);  // leading tabs are empty cells, kept in `line`
    const bool skipped = content.empty() || content.front() == '#';
    if (skipped && !table.rows.empty()) continue;
    const std::vector<std::string> cells = splitCells(line, table.delimiter);
    ParsedLine parsed = skipped ? ParsedLine{} : parseLine(cells, table.decimalComma, lineNumber);
    if (!parsed.numeric) {
      if (!table.rows.empty())
        return csvError("line " + std::to_string(lineNumber) + " is not a row of numbers (got '" +
                        std::string(content.substr(0, 80)) + "'); the header must come before the first numeric row");
      if (!skipped) addLabels(labels, cells);
      continue;
    }
    if (rounding.size() < parsed.rounding.size()) rounding.resize(parsed.rounding.size(), 0.0);
    for (std::size_t c = 0; c < parsed.rounding.size(); ++c) rounding[c] = std::max(rounding[c], parsed.rounding[c]);
    table.rows.push_back(std::move(parsed.row));
  }
  if (table.rows.empty())
    return csvError("the file has no numeric row (" + std::to_string(lines.size()) +
                    " lines, none of them numbers only; delimiter '" +
                    (table.delimiter == '\t' ? std::string("tab") : std::string(1, table.delimiter)) + "')");
  const std::size_t columns = std::max(labels.size(), rounding.size());
  labels.resize(columns);
  rounding.resize(columns, 0.0);
  for (NumericRow& row : table.rows) row.cells.resize(columns);
  table.labels = std::move(labels);
  table.rounding = std::move(rounding);
  return table;
}

}  // namespace linkwright::kinematics::io
