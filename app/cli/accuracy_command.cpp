// linkwright-cli accuracy: the speed-accuracy trade of reading peaks off a sampled cycle,
// measured on the seeds' linkages (sampling_accuracy.h), with the time each choice costs.

#include "app/cli/commands.h"
#include "app/cli/svg_plot.h"

#include "kinematics/analysis/sampling_accuracy.h"
#include "kinematics/design/examples.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/constraint_form.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <ostream>
#include <sstream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatDouble;

constexpr std::size_t kSampleCounts[] = {12, 36, 360, 3600};
constexpr std::size_t kReferenceSamples = 7200;  // refined too: independent of every row's grid
constexpr int kRepeats = 5;
const char* const kDefaultExamples[] = {"miranda-fourbar", "ls3-engine", "shaper", "watt-ii"};

struct Subject {
  std::string name;
  k::Mechanism mechanism;
  double omega = 0.0;
};

k::Result<Subject> subject(const std::string& name) {
  if (const auto e = k::findExample(name)) return Subject{name, e->mechanism, e->omega};
  return k::Error{k::ErrorCode::InvalidValue, "--example",
                  "--example: no example named '" + name + "' (see linkwright-cli examples)"};
}

// The median wall time of a few runs, in microseconds, and the last run's result.
template <typename F>
auto timed(F&& f, double& microseconds) {
  std::vector<double> times;
  auto result = f();
  for (int i = 0; i < kRepeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    result = f();
    times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(times.begin(), times.begin() + kRepeats / 2, times.end());
  microseconds = times[kRepeats / 2];
  return result;
}

struct Row {
  std::string example, method;
  std::size_t samples = 0;
  double microseconds = 0.0;
  k::PeakError error;
  std::string reference = "refined";  ///< what the errors are measured against
};

constexpr double kNewtonTolerances[] = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};
constexpr std::size_t kNewtonSamples = 360;

// The same linkage with every RRR joint solved by Newton, at each tolerance, against the
// closed form at the same samples: this isolates the solver's error from the sampling's.
k::Result<std::vector<Row>> measureNewton(const Subject& s) {
  const auto start = k::solvePose(s.mechanism, {0.0, s.omega, 0.0}, {false, false});
  if (!start) return start.error();
  const k::Mechanism newton = k::withNewtonPoints(s.mechanism, start->position);
  Row closed{s.name, "closed-form", kNewtonSamples, 0.0, {}, "-"};
  const auto exact =
      timed([&] { return k::sampledPeaks(s.mechanism, s.omega, kNewtonSamples, k::DerivativeMethod::Exact); },
            closed.microseconds);
  if (!exact) return exact.error();
  std::vector<Row> rows{closed};
  for (const double tolerance : kNewtonTolerances) {
    Row r{s.name, "newton-" + k::formatShort(tolerance, 1), kNewtonSamples, 0.0, {}, "closed-form"};
    const k::NewtonSettings settings{tolerance, 50};
    const auto read =
        timed([&] { return k::sampledPeaks(newton, s.omega, kNewtonSamples, k::DerivativeMethod::Exact, settings); },
              r.microseconds);
    if (!read) return read.error();
    r.error = k::peakError(*read, *exact);
    rows.push_back(r);
  }
  return rows;
}

k::Result<std::vector<Row>> measure(const Subject& s) {
  const auto reference = k::exactPeaks(s.mechanism, s.omega, kReferenceSamples);
  if (!reference) return k::Error{reference.error().code, "--example", s.name + ": " + reference.error().message};
  std::vector<Row> rows;
  for (const std::size_t n : kSampleCounts) {
    for (const auto& choice :
         {std::pair{"samples", k::DerivativeMethod::Exact}, {"frames", k::DerivativeMethod::FiniteDifference}}) {
      // A plain local, not a structured binding: clang 14 cannot capture those in a lambda.
      const k::DerivativeMethod derivative = choice.second;
      Row r{s.name, choice.first, n, 0.0, {}};
      const auto read = timed([&] { return k::sampledPeaks(s.mechanism, s.omega, n, derivative); }, r.microseconds);
      if (!read) return read.error();
      r.error = k::peakError(*read, *reference);
      rows.push_back(r);
    }
    Row r{s.name, "refined", n, 0.0, {}};
    const auto refined = timed([&] { return k::exactPeaks(s.mechanism, s.omega, n); }, r.microseconds);
    if (!refined) return refined.error();
    r.error = k::peakError(*refined, *reference);
    rows.push_back(r);
  }
  const auto newton = measureNewton(s);
  if (!newton) return newton.error();
  rows.insert(rows.end(), newton->begin(), newton->end());
  return rows;
}

std::string csv(const std::vector<Row>& rows) {
  std::vector<std::vector<std::string>> table;
  table.push_back({"example", "method", "samples_per_rev", "time_us", "omega_rel_error", "alpha_rel_error",
                   "speed_rel_error", "acceleration_rel_error", "angle_error_deg", "reference"});
  for (const Row& r : rows)
    table.push_back({r.example, r.method, std::to_string(r.samples), k::formatShort(r.microseconds, 4),
                     k::formatShort(r.error.omega, 3), k::formatShort(r.error.alpha, 3),
                     k::formatShort(r.error.speed, 3), k::formatShort(r.error.acceleration, 3),
                     k::formatShort(k::radToDeg(r.error.angle), 3), r.reference});
  std::ostringstream out;
  for (const auto& cells : table) {
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << k::io::csvField(cells[i]);
    out << "\r\n";  // RFC 4180, as every CSV Linkwright writes
  }
  return out.str();
}

// Worst rate error over the examples per method and grid; a zero error is drawn at 1e-16
// (round-off), since a log axis has no zero.
std::string plot(const std::vector<Row>& rows) {
  std::map<std::string, std::map<std::size_t, double>> worst;
  for (const Row& r : rows) {
    if (r.reference != "refined") continue;
    double& w = worst[r.method][r.samples];
    w = std::max({w, r.error.worstRate(), 1e-16});
  }
  const std::pair<const char*, const char*> styles[] = {
      {"frames", "#d62728"}, {"samples", "#1f77b4"}, {"refined", "#2ca02c"}};
  const std::map<std::string, std::string> labels{
      {"frames", "frame differences"}, {"samples", "read off samples"}, {"refined", "refined (Linkwright)"}};
  std::vector<PlotSeries> series;
  for (const auto& [method, colour] : styles) {
    PlotSeries s{labels.at(method), colour, std::string(method) == "frames", {}};
    for (const auto& [n, e] : worst[method]) s.points.emplace_back(static_cast<double>(n), e);
    series.push_back(s);
  }
  return logLogPlotSvg("Worst peak error of |ω|, |α|, speed, acceleration (seed linkages)", "samples per revolution",
                       "relative error", series);
}

}  // namespace

ExitCode runAccuracy(const Invocation& inv, std::ostream& out, std::ostream& err) {
  std::vector<std::string> names(std::begin(kDefaultExamples), std::end(kDefaultExamples));
  if (inv.example) names = {*inv.example};
  std::vector<Row> rows;
  for (const std::string& name : names) {
    const auto s = subject(name);
    auto measured = s ? measure(*s) : k::Result<std::vector<Row>>(s.error());
    if (!measured) {
      err << "linkwright-cli: " << measured.error().message << "\n";
      return ExitCode::BadInput;
    }
    rows.insert(rows.end(), measured->begin(), measured->end());
  }
  const std::string table = csv(rows);
  if (inv.svgFile)
    if (const auto e = kinematics::io::writeFileSafely(*inv.svgFile, plot(rows))) {
      err << "linkwright-cli: " << e->message << "\n";
      return ExitCode::IoError;
    }
  if (!inv.outputFile) {
    out << table;
    return ExitCode::Success;
  }
  if (const auto e = kinematics::io::writeFileSafely(*inv.outputFile, table)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
