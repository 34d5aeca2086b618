// linkwright-cli accuracy: the speed-accuracy trade of reading peaks off a sampled cycle,
// measured on the seeds' linkages, with the time each choice costs. The study and its CSV are
// the core's (kinematics/design/accuracy_study.h, kinematics/io/accuracy_csv.h), as Python's
// linkwright.accuracy has them; this command draws the trade as SVG and writes.

#include "app/cli/commands.h"
#include "app/cli/svg_plot.h"

#include "kinematics/design/accuracy_study.h"
#include "kinematics/io/accuracy_csv.h"
#include "kinematics/io/safe_file.h"

#include <algorithm>
#include <map>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// Worst rate error over the examples per method and grid; a zero error is drawn at 1e-16
// (round-off), since a log axis has no zero.
std::string plot(const std::vector<k::AccuracyRow>& rows) {
  std::map<std::string, std::map<std::size_t, double>> worst;
  for (const k::AccuracyRow& r : rows) {
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
  const auto rows = k::measureAccuracy({inv.example, k::FrontEnd::Cli});
  if (!rows) {
    err << "linkwright-cli: " << rows.error().message << "\n";
    return ExitCode::BadInput;
  }
  const std::string table = k::io::accuracyCsv(*rows);
  if (inv.svgFile)
    if (const auto e = kinematics::io::writeFileSafely(*inv.svgFile, plot(*rows))) {
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
