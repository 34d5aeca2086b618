#include "tests/fuzz/table_checks.h"

#include "tests/fuzz/fuzz_checks.h"

#include "kinematics/io/law_table_csv.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/motion_law.h"

#include <cmath>
#include <fstream>

namespace linkwright::fuzz {
namespace {

namespace k = kinematics;

std::string at(const std::string& what, std::size_t index) { return what + "[" + std::to_string(index) + "]"; }

// A refusal must say why, and quote no nan or inf the bytes did not hold.
std::optional<std::string> checkRefusal(const k::Error& error, std::string_view bytes, const std::string& reader) {
  if (error.message.empty()) return reader + ": a refusal without a message";
  if (const auto token = nonFiniteToken(error.message, bytes))
    return reader + ": '" + *token + "' in the message: " + error.message;
  return std::nullopt;
}

// What numeric_table_csv.h documents of a table it returns.
std::optional<std::string> checkTableLayout(const k::io::NumericTable& t, std::string_view bytes) {
  if (bytes.size() > k::io::kMaxNumericTableBytes) return std::string("a table over 64 MiB was read");
  if (t.delimiter != ',' && t.delimiter != ';' && t.delimiter != '\t')
    return "delimiter " + std::to_string(static_cast<int>(t.delimiter));
  if (t.decimalComma != (t.delimiter != ',')) return std::string("decimal comma with a ',' delimiter, or not with ';'");
  if (t.rows.empty()) return std::string("a table without rows");
  if (t.rounding.size() != t.columns()) return std::string("a rounding per column: sizes differ");
  for (std::size_t c = 0; c < t.rounding.size(); ++c)
    if (!(std::isfinite(t.rounding[c]) && t.rounding[c] >= 0.0)) return at("rounding", c) + " not finite and >= 0";
  int lastLine = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const k::io::NumericRow& row = t.rows[r];
    if (row.cells.size() != t.columns()) return at("rows", r) + ": a cell count other than the columns'";
    if (row.line <= lastLine) return at("rows", r) + ": line numbers not increasing";
    lastLine = row.line;
    bool any = false;
    for (std::size_t c = 0; c < row.cells.size(); ++c) {
      if (!row.cells[c]) continue;
      any = true;
      if (!std::isfinite(*row.cells[c])) return at("rows", r) + at(".cells", c) + " not finite";
    }
    if (!any) return at("rows", r) + ": a numeric row without a number";
  }
  return std::nullopt;
}

// What law_table_csv.h and motion_law.h document of a table law; `kind` its driver's.
std::optional<std::string> checkTableLaw(const k::TableLaw& law, k::InputKind kind, std::string_view bytes) {
  const std::size_t n = law.time.size();
  if (n < 4 || law.position.size() != n || law.curvature.size() != n)
    return "a table law of " + std::to_string(n) + " times, " + std::to_string(law.position.size()) + " positions, " +
           std::to_string(law.curvature.size()) + " curvatures";
  for (std::size_t i = 0; i < n; ++i) {
    if (!(std::abs(law.time[i]) <= 1e6)) return at("time", i) + " not within ±1e6 s";
    if (!(std::abs(law.position[i]) <= k::kMaxLength)) return at("position", i) + " not within the input domain";
    if (i > 0 && !(law.time[i] > law.time[i - 1])) return at("time", i) + " not later than the row before";
  }
  const k::MotionLaw motion = law;
  if (const auto refused = k::checkMotionLaw(motion, kind)) return checkRefusal(*refused, bytes, "checkMotionLaw");
  // Accepted: the spline and its state are finite at every row and between rows.
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(law.curvature[i])) return at("curvature", i) + " not finite in an accepted law";
    for (const double t : {law.time[i], i + 1 < n ? 0.5 * (law.time[i] + law.time[i + 1]) : law.time[i]}) {
      const k::DriverState s = k::motionAt(motion, t);
      if (!(std::isfinite(s.position) && std::isfinite(s.velocity) && std::isfinite(s.acceleration)))
        return "a state that is not finite at t = " + k::formatNumber(t) + " in an accepted law";
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> checkCompareTable(std::string_view bytes, const std::string& scratchPath) {
  const auto table = k::io::readNumericTable(bytes);
  if (!table) return checkRefusal(table.error(), bytes, "readNumericTable");
  if (auto finding = checkTableLayout(*table, bytes)) return "readNumericTable: " + *finding;
  if (table->rows.size() > kMaxComparedRows) return std::nullopt;
  {
    std::ofstream file(scratchPath, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!file) return "cannot write the scratch file " + scratchPath;
  }
  // The mapping the headers propose, compared with the thesis crank-rocker's exact solution: a
  // refusal (exit 2) is expected for most tables, never a crash or a non-finite number.
  const std::vector<std::string> compare{"compare", "--example", "thesis-crank-rocker", scratchPath, "--map", "auto"};
  int code = 0;
  if (auto finding = checkCliRun(compare, bytes, &code)) return finding;
  if (code == 2) return std::nullopt;
  std::vector<std::string> json = compare;
  json.push_back("--json");
  return checkCliRun(json, bytes);
}

std::optional<std::string> checkLawTable(std::string_view bytes) {
  for (const auto kind : {k::InputKind::Angle, k::InputKind::Length}) {
    const auto law = k::io::readLawTableCsv(bytes, kind, "mm");
    const std::string reader = kind == k::InputKind::Angle ? "readLawTableCsv (crank)" : "readLawTableCsv (mm)";
    if (!law) {
      if (auto finding = checkRefusal(law.error(), bytes, reader)) return finding;
      continue;
    }
    if (auto finding = checkTableLaw(*law, kind, bytes)) return reader + ": " + *finding;
  }
  return std::nullopt;
}

}  // namespace linkwright::fuzz
