// `linkwright-cli atlas`: the coupler-curve atlas (kinematics/explore/coupler_atlas.h): every
// cell of a grid of four-bars over link ratios and coupler-point places, its Grashof class, how
// its crank moves and what its curve has (cusps, crunodes, symmetry, straight and circular
// runs, with where), the cells --filter keeps; as text, one JSON object, or with -o a CSV
// through the one writer. With --cell I, that cell's linkage written as a design document.

#include "app/cli/commands.h"

#include "app/cli/atlas_options.h"
#include "app/cli/progress.h"

#include "kinematics/io/csv_writer.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <ostream>
#include <sstream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

std::string pointText(const Eigen::Vector2d& p) {
  return "(" + formatShort(p.x(), 4) + ", " + formatShort(p.y(), 4) + ")";
}
std::string degText(double rad) { return formatShort(k::radToDeg(rad), 4) + "°"; }
double axisDeg(const k::SymmetryAxis& a) { return k::radToDeg(std::atan2(a.direction.y(), a.direction.x())); }

// What a cell's curve has, for a person: each feature with where.
std::string featuresText(const k::AtlasCell& cell) {
  if (cell.motion == k::CrankMotion::NeverAssembles) return "-";
  const k::CurveFeatures& f = cell.features;
  std::vector<std::string> parts;
  for (const k::Cusp& c : f.cusps) parts.push_back("cusp at " + degText(c.crankAngle) + " " + pointText(c.point));
  for (const k::Crunode& c : f.crunodes) parts.push_back("crunode " + pointText(c.point));
  if (f.symmetry)
    parts.push_back("symmetric about " + pointText(f.symmetry->point) + " at " + formatShort(axisDeg(*f.symmetry), 4) +
                    "°");
  if (f.straight)
    parts.push_back("straight " + formatShort(f.straight->length, 4) + " long, " + degText(f.straight->fromAngle) +
                    "→" + degText(f.straight->toAngle));
  if (f.circular)
    parts.push_back("circular r " + formatShort(f.circular->radius, 4) + " about " + pointText(f.circular->centre) +
                    ", " + degText(f.circular->fromAngle) + "→" + degText(f.circular->toAngle));
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : "; ") + p;
  return text.empty() ? "none" : text;
}

const std::vector<std::string> kCsvHeader{"cell",
                                          "coupler",
                                          "rocker",
                                          "frame",
                                          "along",
                                          "across",
                                          "branch",
                                          "class",
                                          "crank",
                                          "from_deg",
                                          "to_deg",
                                          "size",
                                          "cusps",
                                          "crunodes",
                                          "cusp_deg",
                                          "cusp_x",
                                          "cusp_y",
                                          "crunode_x",
                                          "crunode_y",
                                          "symmetry_x",
                                          "symmetry_y",
                                          "symmetry_deg",
                                          "straight_from_deg",
                                          "straight_to_deg",
                                          "straight_length",
                                          "straight_deviation",
                                          "circular_from_deg",
                                          "circular_to_deg",
                                          "circular_radius",
                                          "circular_deviation"};

std::string csvRow(std::size_t index, const k::AtlasCell& c) {
  const auto num = [](double v) { return k::formatDouble(v); };
  const auto deg = [](double v) { return k::formatDouble(k::radToDeg(v)); };
  const k::CurveFeatures& f = c.features;
  const bool traced = c.motion != k::CrankMotion::NeverAssembles;
  std::vector<std::string> v{std::to_string(index),
                             num(c.key.lengths.coupler),
                             num(c.key.lengths.rocker),
                             num(c.key.lengths.frame),
                             num(c.key.point.along),
                             num(c.key.point.across),
                             c.key.branch == k::Branch::Open ? "open" : "crossed",
                             std::string(k::toString(c.grashof.category)),
                             std::string(k::toString(c.motion)),
                             traced ? deg(c.range.from) : "",
                             traced ? deg(c.range.to) : "",
                             traced ? num(f.size) : "",
                             std::to_string(f.cusps.size()),
                             std::to_string(f.crunodes.size())};
  const auto add = [&](bool has, std::initializer_list<std::string> values) {
    for (const std::string& s : values) v.push_back(has ? s : "");
  };
  const bool cusp = !f.cusps.empty(), crunode = !f.crunodes.empty();
  add(cusp, {cusp ? deg(f.cusps[0].crankAngle) : "", cusp ? num(f.cusps[0].point.x()) : "",
             cusp ? num(f.cusps[0].point.y()) : ""});
  add(crunode, {crunode ? num(f.crunodes[0].point.x()) : "", crunode ? num(f.crunodes[0].point.y()) : ""});
  add(f.symmetry.has_value(),
      {f.symmetry ? num(f.symmetry->point.x()) : "", f.symmetry ? num(f.symmetry->point.y()) : "",
       f.symmetry ? num(axisDeg(*f.symmetry)) : ""});
  add(f.straight.has_value(),
      {f.straight ? deg(f.straight->fromAngle) : "", f.straight ? deg(f.straight->toAngle) : "",
       f.straight ? num(f.straight->length) : "", f.straight ? num(f.straight->deviation) : ""});
  add(f.circular.has_value(),
      {f.circular ? deg(f.circular->fromAngle) : "", f.circular ? deg(f.circular->toAngle) : "",
       f.circular ? num(f.circular->radius) : "", f.circular ? num(f.circular->deviation) : ""});
  std::string row;
  for (std::size_t i = 0; i < v.size(); ++i) row += (i ? "," : "") + k::io::csvField(v[i]);
  return row + "\n";
}

k::io::JsonValue cellJson(std::size_t index, const k::AtlasCell& c) {
  const auto point = [](const Eigen::Vector2d& p) { return k::io::JsonValue::array({p.x(), p.y()}); };
  const k::CurveFeatures& f = c.features;
  k::io::JsonValue cusps = k::io::JsonValue::array(), crunodes = k::io::JsonValue::array();
  for (const k::Cusp& x : f.cusps)
    cusps.push_back({{"crank_deg", k::radToDeg(x.crankAngle)}, {"point", point(x.point)}, {"speed", x.speed}});
  for (const k::Crunode& x : f.crunodes)
    crunodes.push_back(
        {{"point", point(x.point)}, {"crank_deg", {k::radToDeg(x.crankAngles[0]), k::radToDeg(x.crankAngles[1])}}});
  k::io::JsonValue json{{"cell", index},
                        {"coupler", c.key.lengths.coupler},
                        {"rocker", c.key.lengths.rocker},
                        {"frame", c.key.lengths.frame},
                        {"along", c.key.point.along},
                        {"across", c.key.point.across},
                        {"branch", c.key.branch == k::Branch::Open ? "open" : "crossed"},
                        {"class", k::toString(c.grashof.category)},
                        {"crank", k::toString(c.motion)},
                        {"size", f.size},
                        {"cusps", cusps},
                        {"crunodes", crunodes},
                        {"symmetry", nullptr},
                        {"straight", nullptr},
                        {"circular", nullptr}};
  if (c.motion != k::CrankMotion::NeverAssembles)
    json["crank_range_deg"] = {k::radToDeg(c.range.from), k::radToDeg(c.range.to)};
  if (f.symmetry)
    json["symmetry"] = {
        {"point", point(f.symmetry->point)}, {"axis_deg", axisDeg(*f.symmetry)}, {"deviation", f.symmetry->deviation}};
  if (f.straight)
    json["straight"] = {{"from_deg", k::radToDeg(f.straight->fromAngle)},
                        {"to_deg", k::radToDeg(f.straight->toAngle)},
                        {"from", point(f.straight->from)},
                        {"to", point(f.straight->to)},
                        {"length", f.straight->length},
                        {"deviation", f.straight->deviation}};
  if (f.circular)
    json["circular"] = {{"from_deg", k::radToDeg(f.circular->fromAngle)},
                        {"to_deg", k::radToDeg(f.circular->toAngle)},
                        {"centre", point(f.circular->centre)},
                        {"radius", f.circular->radius},
                        {"turn_deg", k::radToDeg(f.circular->turn)},
                        {"deviation", f.circular->deviation}};
  return json;
}

// One line a kept cell, for a person.
std::string cellLine(std::size_t i, const k::AtlasCell& c) {
  return std::to_string(i) + "  coupler " + formatShort(c.key.lengths.coupler) + " rocker " +
         formatShort(c.key.lengths.rocker) + " frame " + formatShort(c.key.lengths.frame) + " P (" +
         formatShort(c.key.point.along) + ", " + formatShort(c.key.point.across) + ")  " +
         std::string(k::toString(c.grashof.category)) + ", " + std::string(k::toString(c.motion)) + ": " +
         featuresText(c) + "\n";
}

// `text` (a JSON dump) with every line after the first indented by `by` spaces, to sit inside
// an object written piece by piece.
std::string indented(const std::string& text, std::size_t by) {
  std::string out;
  for (const char ch : text) {
    out += ch;
    if (ch == '\n') out.append(by, ' ');
  }
  return out;
}

// What each feature is found to (coupler_curve_features.h), for --json.
k::io::JsonValue tolerancesJson(std::size_t samples) {
  const k::ClassifierTolerances t = k::classifierTolerances(samples);
  return {{"of", "S, the diagonal of the curve's bounding box, except angles"},
          {"cusp", {{"speed_per_rad", t.cuspSpeed}, {"crank_rad", t.cuspAngle}, {"point", t.cuspPoint}}},
          {"crunode",
           {{"least_crossing_deg", t.crossingAngleDeg},
            {"same_point", t.samePoint},
            {"point", t.crunodePoint},
            {"crank_rad", t.crunodeAngle}}},
          {"symmetry", {{"deviation", t.symmetry}, {"axis_rad", t.symmetryAxis}}},
          {"straight", {{"deviation", t.straight}, {"least_length", t.straightLength}, {"ends_u_rad", t.runEnd}}},
          {"circular",
           {{"deviation", t.circular},
            {"least_length", t.arcLength},
            {"least_turn_deg", t.arcTurnDeg},
            {"ends_u_rad", t.runEnd}}}};
}

ExitCode writeCell(const AtlasOptions& o, std::ostream& out, std::ostream& err) {
  const k::AtlasCellKey key = k::atlasCellKey(o.axes, *o.cell);
  const auto design = k::atlasCellDesign(key, o.crank, o.lengthUnit);
  if (!design) {
    err << "linkwright-cli: --cell " << *o.cell << ": " << design.error().message << "\n";
    return design.error().code == k::ErrorCode::NotAssemblable ? ExitCode::NotAssemblable : ExitCode::BadInput;
  }
  if (auto e = k::io::writeFileSafely(*o.outputFile, k::io::writeDocument(*design))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  out << "atlas cell " << *o.cell << ": four-bar crank " << formatShort(o.crank) << ", coupler "
      << formatShort(key.lengths.coupler * o.crank) << ", rocker " << formatShort(key.lengths.rocker * o.crank)
      << ", frame " << formatShort(key.lengths.frame * o.crank) << " " << o.lengthUnit << ", P "
      << formatShort(key.point.along) << " along and " << formatShort(key.point.across)
      << " across the coupler (coupler lengths); written to " << *o.outputFile << "\n";
  return ExitCode::Success;
}

}  // namespace

ExitCode runAtlas(const AtlasOptions& o, std::ostream& out, std::ostream& err) {
  if (o.cell) return writeCell(o, out, err);
  const std::size_t count = k::atlasCellCount(o.axes);
  // Each cell is written as it is classified (a CSV row to -o, a line or a JSON entry to the
  // output) and then dropped: nothing grows with the cells. The progress line is cleared
  // before each write to a terminal and drawn again after.
  const bool outputOnTerminal = !progressShown(err, &out) && isTerminal(err);
  Progress progress(err, "atlas", "cells", isTerminal(err));
  std::size_t kept = 0;
  std::optional<k::Error> refused;  // the core's, as opposed to the output's
  if (o.json)
    out << "{\n  \"cells\": " << count << ",\n  \"samples\": " << o.axes.samples
        << ",\n  \"tolerances\": " << indented(tolerancesJson(o.axes.samples).dump(2), 2) << ",\n  \"atlas\": [";
  else
    out << "coupler-curve atlas: " << count << (count == 1 ? " cell" : " cells")
        << " (crank 1; coupler, rocker, frame in crank lengths; P along and "
        << "across B→C in coupler lengths; points in crank lengths, O2 at the origin, O4 on +x), " << o.axes.samples
        << " samples a curve\n";
  const auto run = [&](std::ostream* csv) -> std::optional<std::string> {
    if (csv) {
      for (std::size_t i = 0; i < kCsvHeader.size(); ++i) *csv << (i ? "," : "") << kCsvHeader[i];
      *csv << "\n";
    }
    const auto visit = [&](std::size_t i, const k::AtlasCell& c) {
      if (!k::matchesFilter(c, o.filter)) return true;
      if (csv) *csv << csvRow(i, c);
      if (outputOnTerminal) progress.clear();
      if (o.json) out << (kept ? ",\n    " : "\n    ") << indented(cellJson(i, c).dump(2), 4);
      else out << cellLine(i, c);
      ++kept;
      return !csv || static_cast<bool>(*csv);  // a failed write stops the run; the writer says why
    };
    k::RunControl control;
    control.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    auto ran = k::runAtlas(o.axes, 0, count, visit, control);
    if (!ran) refused = ran.error();
    return refused ? std::optional{refused->message} : std::nullopt;
  };
  std::optional<k::Error> problem;
  if (o.outputFile) problem = k::io::writeStreamSafely(*o.outputFile, [&](std::ostream& csv) { return run(&csv); });
  else run(nullptr);
  progress.clear();
  if (o.json) out << (kept ? "\n  ],\n" : "],\n") << "  \"matching\": " << kept << "\n}\n";
  else
    out << kept << " match" << (kept == 1 ? "es" : "")
        << (o.outputFile && !problem ? "; written to " + *o.outputFile : std::string()) << "\n";
  out << std::flush;
  if (refused) {
    err << "linkwright-cli: " << refused->message << "\n";
    return ExitCode::BadInput;
  }
  if (problem) {
    err << "linkwright-cli: " << problem->message << "\n";
    return ExitCode::IoError;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
