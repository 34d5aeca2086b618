#include "app/cli/commands.h"

#include "kinematics/io/bounded_read.h"
#include "kinematics/io/law_table_csv.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::Error;
using k::ErrorCode;

constexpr long long kDefaultTimeSamples = 361;

Error badValue(const std::string& option, const std::string& why) {
  return Error{ErrorCode::InvalidValue, option, option + " " + why};
}

// A measured q(t) (io/law_table_csv.h), from a regular file of at most 64 MiB (io/bounded_read.h).
k::Result<k::TableLaw> readLawTable(const std::string& path, const GridDefaults& d) {
  const auto text = k::io::readFileBounded(path, k::io::kMaxLawTableBytes, "a table");
  if (!text) return badValue("--law-table", text.error().message);
  auto law = k::io::readLawTableCsv(*text, d.input, d.lengthUnit);
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
  auto table = readLawTable(*inv.lawTable, d);
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
    return badValue("--to-time", "must not be before --from-time (got " + k::formatShort(from) + " to " +
                                     k::formatShort(*end) + " s)");
  long long samples = inv.samples.value_or(kDefaultTimeSamples);
  if (inv.stepTime) {
    const double intervals = std::floor((*end - from) / *inv.stepTime + 1e-9);
    if (intervals + 1.0 > static_cast<double>(k::kMaxSamples))
      return badValue("--step-time", "is too small: it would give " + k::formatShort(intervals + 1.0) +
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
