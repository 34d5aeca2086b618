#include "kinematics/io/law_table_csv.h"

#include "kinematics/model/units.h"

#include <charconv>
#include <optional>
#include <vector>

namespace linkwright::kinematics::io {
namespace {

std::string_view trimmed(std::string_view cell) {
  while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.remove_suffix(1);
  while (!cell.empty() && cell.front() == ' ') cell.remove_prefix(1);
  return cell;
}

std::optional<double> parseCell(std::string_view cell) {
  cell = trimmed(cell);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (ec != std::errc{} || end != cell.data() + cell.size() || cell.empty()) return std::nullopt;
  return value;
}

Error tableError(const std::string& why) { return Error{ErrorCode::InvalidValue, "law.table", why}; }

}  // namespace

Result<TableLaw> readLawTableCsv(std::string_view text, InputKind kind, const std::string& lengthUnit) {
  if (text.size() > kMaxLawTableBytes) return tableError("the table is larger than 64 MiB");
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte-order mark (Excel's)
  const auto nextLine = [&text]() {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    return trimmed(line);
  };
  const std::string_view header = nextLine();
  const std::size_t comma = header.find(',');
  const std::string_view name =
      comma == std::string_view::npos ? std::string_view{} : trimmed(header.substr(comma + 1));
  const bool angle = kind == InputKind::Angle;
  const std::string lengthSuffix = "_" + lengthUnit;
  const bool degrees = angle && name.size() > 4 && name.ends_with("_deg");
  const bool radians = angle && name.size() > 4 && name.ends_with("_rad");
  const bool length = !angle && name.size() > lengthSuffix.size() && name.ends_with(lengthSuffix);
  if (trimmed(header.substr(0, comma)) != "time_s" || !(degrees || radians || length))
    return tableError(std::string("the first line must name the columns time_s and the ") +
                      (angle ? "angle in _deg or _rad, e.g. time_s,crank_angle_deg"
                             : "position in the linkage's unit, e.g. time_s,position" + lengthSuffix) +
                      " (got '" + std::string(header) + "')");
  std::vector<double> time, position;
  for (int row = 2; !text.empty(); ++row) {
    const std::string_view line = nextLine();
    if (line.empty()) continue;
    const std::size_t at = line.find(',');
    const auto t = parseCell(line.substr(0, at));
    const auto q = at == std::string_view::npos ? std::nullopt : parseCell(line.substr(at + 1));
    if (!t || !q)
      return tableError("line " + std::to_string(row) + ": expected two numbers (got '" + std::string(line) + "')");
    time.push_back(*t);
    position.push_back(degrees ? degToRad(*q) : *q);
  }
  return makeTableLaw(std::move(time), std::move(position));
}

}  // namespace linkwright::kinematics::io
