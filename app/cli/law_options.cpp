#include "app/cli/commands.h"

#include "kinematics/io/number_format.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::Error;
using k::ErrorCode;

constexpr long long kDefaultTimeSamples = 361;
constexpr std::uintmax_t kMaxTableBytes = 64u << 20;

Error badValue(const std::string& option, const std::string& why) {
  return Error{ErrorCode::InvalidValue, option, option + " " + why};
}

std::optional<double> parseCell(std::string cell) {
  while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
  while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
  double value = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (ec != std::errc{} || end != cell.data() + cell.size() || cell.empty()) return std::nullopt;
  return value;
}

// A measured θ(t): a header naming the time in s and the angle in degrees or radians
// ("time_s,crank_angle_deg"), then one row per instant.
k::Result<k::TableLaw> readLawTable(const std::string& path) {
  // A table is a file of text: not a device or a pipe, and not larger than a measurement is.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) > kMaxTableBytes)
    return badValue("--law-table",
                    path + " cannot be opened for reading as a table (a regular file of at most 64 MiB)");
  std::ifstream file(path);
  if (!file) return badValue("--law-table", path + " cannot be opened for reading");
  std::string header;
  std::getline(file, header);
  if (!header.empty() && header.back() == '\r') header.pop_back();
  const std::size_t comma = header.find(',');
  const std::string angleName = comma == std::string::npos ? "" : header.substr(comma + 1);
  const bool degrees = angleName.size() > 4 && angleName.ends_with("_deg");
  const bool radians = angleName.size() > 4 && angleName.ends_with("_rad");
  if (header.substr(0, comma) != "time_s" || !(degrees || radians))
    return badValue("--law-table", path +
                                       ": the first line must name the columns time_s and the angle in _deg or "
                                       "_rad, e.g. time_s,crank_angle_deg (got '" +
                                       header + "')");
  std::vector<double> time, angle;
  std::string line;
  for (int row = 2; std::getline(file, line); ++row) {
    if (line.empty() || line == "\r") continue;
    const std::size_t at = line.find(',');
    const auto t = parseCell(line.substr(0, at));
    const auto q = at == std::string::npos ? std::nullopt : parseCell(line.substr(at + 1));
    if (!t || !q)
      return badValue("--law-table",
                      path + " line " + std::to_string(row) + ": expected two numbers (got '" + line + "')");
    time.push_back(*t);
    angle.push_back(degrees ? k::degToRad(*q) : *q);
  }
  auto law = k::makeTableLaw(std::move(time), std::move(angle));
  if (!law) return badValue("--law-table", path + ": " + law.error().message);
  return law;
}

// The law the options describe, starting at --from at the driver speed of --rpm / --omega;
// --rise in degrees for a crank, in the length unit for a linear driver.
k::Result<k::MotionLaw> lawFor(const Invocation& inv, const GridDefaults& d, double start, double omega) {
  const std::string& name = *inv.law;
  if (name == "constant") return k::MotionLaw{k::ConstantVelocity{start, omega}};
  if (name == "ramp") return k::MotionLaw{k::RampToSpeed{start, omega, *inv.rampTime}};
  if (name == "cycloidal") return k::MotionLaw{k::CycloidalRise{start, d.toInput(*inv.riseDeg), *inv.duration}};
  if (name == "345") return k::MotionLaw{k::PolynomialRise{start, d.toInput(*inv.riseDeg), *inv.duration}};
  auto table = readLawTable(*inv.lawTable);
  if (!table) return table.error();
  return k::MotionLaw{std::move(*table)};
}

// Where a law's table ends by default: a rise's end, a ramp and one turn at speed, one turn.
std::optional<double> defaultEndTime(const k::MotionLaw& law, double omega) {
  if (const auto span = k::lawTimeSpan(law)) return span->second;
  if (const auto* rise = std::get_if<k::CycloidalRise>(&law)) return rise->duration;
  if (const auto* rise = std::get_if<k::PolynomialRise>(&law)) return rise->duration;
  if (omega == 0.0) return std::nullopt;
  const double turn = 2.0 * k::kPi / std::abs(omega);
  if (const auto* ramp = std::get_if<k::RampToSpeed>(&law)) return ramp->rampTime + turn;
  return turn;
}

}  // namespace

kinematics::Result<kinematics::SweepSpec> timeSweepSpecFor(const Invocation& inv, const GridDefaults& d) {
  const double omega = inv.rpm ? k::rpmToRadPerSec(*inv.rpm) : inv.omega.value_or(d.omega);
  auto law = lawFor(inv, d, d.toInput(inv.fromDeg.value_or(d.fromDeg)), omega);
  if (!law) return law.error();
  if (auto e = k::checkMotionLaw(*law, d.input)) return badValue("--law", "gives " + e->message);
  const auto span = k::lawTimeSpan(*law);
  const double from = inv.fromTime.value_or(span ? span->first : 0.0);
  const auto end = inv.toTime ? inv.toTime : defaultEndTime(*law, omega);
  if (!end) return badValue("--to-time", "is needed: the crank does not turn, so no default end time follows");
  if (*end < from)
    return badValue("--to-time", "must not be before --from-time (got " + k::io::formatShort(from) + " to " +
                                     k::io::formatShort(*end) + " s)");
  long long samples = inv.samples.value_or(kDefaultTimeSamples);
  if (inv.stepTime) {
    const double intervals = std::floor((*end - from) / *inv.stepTime + 1e-9);
    if (intervals + 1.0 > static_cast<double>(k::kMaxSamples))
      return badValue("--step-time", "is too small: it would give " + k::io::formatShort(intervals + 1.0) +
                                         " rows (at most " + std::to_string(k::kMaxSamples) + ")");
    samples = static_cast<long long>(intervals) + 1;
  }
  if (samples < 1 || samples > k::kMaxSamples)
    return badValue("--samples", "must be between 1 and " + std::to_string(k::kMaxSamples) + " (got " +
                                     std::to_string(samples) + ")");
  k::SweepSpec spec;
  spec.samples = static_cast<std::size_t>(samples);
  const double last = inv.stepTime ? from + static_cast<double>(samples - 1) * *inv.stepTime : *end;
  spec.time = k::TimeBase{std::move(*law), from, last};
  if (auto e = k::checkSweepSpec(spec, d.input)) return badValue("--from-time", "/ --to-time: " + e->message);
  return spec;
}

}  // namespace linkwright::cli
