// `linkwright-cli cognates`: a four-bar's two Roberts–Chebyshev cognates
// (kinematics/explore/cognates.h), each written as a document PREFIX-1.linkwright and
// PREFIX-2.linkwright with its coupler point named P, and a table of the three: ground pivots,
// lengths, Grashof class, worst transmission angle over the cycle, and the speed each crank must
// turn at for the three to move together. Text for reading, or one JSON object.

#include "app/cli/commands.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/explore/cognates.h"
#include "kinematics/io/cognates_json.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <ostream>
#include <vector>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

// The design the invocation names: a document, an example or --fourbar lengths; with
// --coupler-point U,V its point P placed there (added if it has none).
k::Result<k::Design> designFor(const Invocation& inv) {
  auto design = inv.fourBar ? k::fourBarDesign(*inv.fourBar, k::Branch::Open, inv.lengthUnit) : resolveDesign(inv);
  if (!design || !inv.couplerPoint) return design;
  const auto fourBar = k::asFourBar(design->mechanism);
  if (!fourBar) return design;  // cognates() says it is not a four-bar
  for (const auto& [value, field] :
       {std::pair{inv.couplerPoint->along, "coupler point along"}, {inv.couplerPoint->across, "coupler point across"}})
    if (auto e = k::checkCoordinate(value, field))
      return k::Error{e->code, "--coupler-point", "--coupler-point: " + e->message};
  auto m = k::withCouplerPoint(design->mechanism, *fourBar, *inv.couplerPoint);
  if (!m) return m.error();
  design.value().mechanism = std::move(*m);
  return design;
}

std::string pointText(const Eigen::Vector2d& p) { return "(" + formatShort(p.x()) + ", " + formatShort(p.y()) + ")"; }

std::string degreesText(const std::optional<double>& radians) {
  return radians ? k::formatFixed(k::radToDeg(*radians), 2) + "°" : k::kUndefinedText;
}

// What a four-bar's crank turns at, against the original crank's ω2, in a table cell.
std::string speedCell(const k::CognateFourBar& f) {
  switch (f.turnsWith[0]) {
  case k::OriginalLink::Crank: return "ω2 (1:1, constant)";
  case k::OriginalLink::Coupler:
    if (!f.crankSpeedRatioMin || !f.crankSpeedRatioMax) return "ω3 (varies)";
    return "ω3 = " + formatShort(*f.crankSpeedRatioMin, 3) + "…" + formatShort(*f.crankSpeedRatioMax, 3) +
           " × ω2 (varies)";
  case k::OriginalLink::Rocker: return "ω4 (varies)";
  }
  return "";
}

void printTable(std::ostream& out, const k::CognateSet& set) {
  const std::vector<std::string> header{"",        "crank pivot", "rocker pivot", "frame",   "crank",
                                        "coupler", "rocker",      "class",        "worst μ", "crank speed"};
  std::vector<std::vector<std::string>> rows{header};
  const std::array<const k::CognateFourBar*, 3> bars{&set.original, &set.cognates[0], &set.cognates[1]};
  const std::array<std::string, 3> names{"original", "cognate 1", "cognate 2"};
  for (std::size_t i = 0; i < 3; ++i) {
    const k::CognateFourBar& f = *bars[i];
    const k::FourBarLengths& l = f.fourBar.lengths;
    rows.push_back({names[i], pointText(f.crankPivot), pointText(f.rockerPivot), formatShort(l.frame),
                    formatShort(l.crank), formatShort(l.coupler), formatShort(l.rocker),
                    std::string(k::toString(f.grashof.category)), degreesText(f.worstTransmission), speedCell(f)});
  }
  // Widths in characters, not bytes: "μ", "ω", "…" and "×" are two bytes each in UTF-8.
  const auto width = [](const std::string& s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::vector<std::size_t> widths(header.size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], width(row[c]));
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c)
      line += row[c] + (c + 1 < row.size() ? std::string(widths[c] - width(row[c]) + 2, ' ') : "");
    out << line << "\n";
  }
}

// Which original link each of a cognate's links turns with, and how to drive it in step.
void printSpeeds(std::ostream& out, const k::CognateFourBar& f, const std::string& name, const std::string& file) {
  out << name << " (" << file << "): its crank turns with the original's " << k::toString(f.turnsWith[0])
      << ", its coupler with the " << k::toString(f.turnsWith[1]) << ", its rocker with the "
      << k::toString(f.turnsWith[2]) << " (each at that link's ω).\n  ";
  if (f.turnsWith[0] == k::OriginalLink::Crank)
    out << "Drive its crank at the original crank's ω (ratio 1, a constant speed) and the three move together.\n";
  else
    out << "For the three to move together its crank must turn at the original coupler's ω3, which is not constant"
        << (f.crankSpeedRatioMin && f.crankSpeedRatioMax
                ? ": from " + formatShort(*f.crankSpeedRatioMin, 4) + " to " + formatShort(*f.crankSpeedRatioMax, 4) +
                      " times the original crank's ω over the cycle"
                : std::string())
        << "; no constant crank speed does it.\n";
  if (!f.grashof.inputFullyRotates)
    out << "  Its crank rocks, from " << formatShort(f.design.fromDeg, 5) << "° to " << formatShort(f.design.toDeg, 5)
        << "° (its document's grid): driven by it, it traces the part of the curve on one assembly branch.\n";
}

}  // namespace

ExitCode runCognates(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto design = designFor(inv);
  if (!design) {
    err << "linkwright-cli: " << design.error().message << "\n";
    return ExitCode::BadInput;
  }
  const auto set = k::cognates(*design, inv.couplerPointName);
  if (!set) {
    const k::Error& e = set.error();
    const bool named = e.field == "couplerPoint" && inv.couplerPointName;
    const bool none = e.field == "couplerPoint" && e.message.find("no point fixed on its coupler") != std::string::npos;
    err << "linkwright-cli: " << (named ? "--coupler-point: " : "") << e.message
        << (none ? " (--coupler-point U,V adds P, U along B→C and V across it)" : "") << "\n";
    return e.code == k::ErrorCode::NotAssemblable ? ExitCode::NotAssemblable : ExitCode::BadInput;
  }
  // Both documents first, then the files: a refusal writes nothing.
  const std::array<std::string, 2> files{*inv.outputFile + "-1.linkwright", *inv.outputFile + "-2.linkwright"};
  for (std::size_t i = 0; i < 2; ++i)
    if (auto e = k::io::writeFileSafely(files[i], k::io::writeDocument(set->cognates[i].design))) {
      err << "linkwright-cli: " << e->message << (i == 1 ? " (" + files[0] + " was written)" : std::string()) << "\n";
      return ExitCode::IoError;
    }
  const std::string& unit = design->mechanism.lengthUnit;
  if (inv.json) {
    out << k::io::cognatesJson(*set, unit, {files[0], files[1]}).dump(2) << "\n";
    return ExitCode::Success;
  }
  out << "cognates of the coupler point " << set->couplerPoint << " (z = " << formatShort(set->z.real(), 5)
      << (set->z.imag() < 0.0 ? " − " : " + ") << formatShort(std::abs(set->z.imag()), 5) << "i: " << set->couplerPoint
      << " = B + z (C − B)), built at the original's crank angle " << formatShort(k::radToDeg(set->constructedAt), 5)
      << "°; third ground pivot O6 at " << pointText(set->thirdPivot) << " " << unit << "\n";
  printTable(out, *set);
  out << "lengths and pivots in " << unit
      << "; worst μ: the transmission angle's farthest from 90° over the motion each makes in the cycle, as "
         "min(μ, 180° − μ)\n";
  printSpeeds(out, set->cognates[0], "cognate 1", files[0]);
  printSpeeds(out, set->cognates[1], "cognate 2", files[1]);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
