// Prints a synthesis report as an aligned text table or as JSON. Numbers are locale-independent
// (std::to_chars through number_text.h); JSON strings go through the core's jsonQuote.

#include "app/cli/synthesize_report.h"

#include "kinematics/io/json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatFixed;
using k::formatJsonNumber;
using k::formatShort;
using Kind = SynthesisDetail::Kind;

std::string grashofName(const k::SynthesisCandidate& c) {
  return c.grashof ? std::string(k::toString(c.grashof->category)) : "-";
}

// Each kind once, in the order found.
std::string defectKinds(const k::SynthesisCandidate& c) {
  if (c.defects.empty()) return "none";
  std::vector<k::DefectKind> seen;
  std::string kinds;
  for (const k::Defect& d : c.defects)
    if (std::find(seen.begin(), seen.end(), d.kind) == seen.end()) {
      seen.push_back(d.kind);
      kinds += (kinds.empty() ? "" : ", ") + std::string(k::toString(d.kind));
    }
  return kinds;
}

// Width in code points, so "μ", "°" and "−" count once.
std::size_t length(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// Columns padded to their widest cell: numbers right-aligned, the last column left-aligned.
void writeTable(const std::vector<std::vector<std::string>>& rows, std::ostream& out) {
  std::vector<std::size_t> width(rows.front().size(), 0);
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], length(row[i]));
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i) {
      const std::string pad(width[i] - length(row[i]), ' ');
      line += (i ? "  " : "") + (i + 1 == row.size() ? row[i] : pad + row[i]);
    }
    out << line << "\n";
  }
}

std::vector<std::vector<std::string>> tableOf(const SynthesisReport& r, std::size_t chosen) {
  const bool family = !r.rows.empty() && r.rows.front().parameter.has_value();
  std::vector<std::string> header{"# "};
  if (family) header.push_back("parameter");
  for (const auto& [name, value] : r.rows.front().dimensions) header.push_back(name);
  if (!r.errorName.empty()) header.push_back("error (" + r.errorUnit + ")");
  for (const char* h : {"Grashof", "min μ (deg)", "defects"}) header.push_back(h);
  std::vector<std::vector<std::string>> rows{header};
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const CandidateRow& row = r.rows[i];
    std::vector<std::string> cells{std::to_string(i + 1) + (i == chosen ? "*" : " ")};
    if (family) cells.push_back(formatFixed(*row.parameter, 6));
    for (const auto& [name, value] : row.dimensions) cells.push_back(formatShort(value));
    if (!r.errorName.empty()) cells.push_back(formatShort(row.candidate.error * r.errorFactor));
    cells.push_back(grashofName(row.candidate));
    cells.push_back(formatFixed(k::radToDeg(row.candidate.minTransmission), 2));
    cells.push_back(defectKinds(row.candidate));
    rows.push_back(std::move(cells));
  }
  return rows;
}

std::string detailText(const SynthesisDetail& d, const std::string& unit) {
  if (d.kind == Kind::Text) return d.text;
  std::string text;
  for (const double v : d.values)
    text += (text.empty() ? "" : ", ") + formatShort(v) + (d.kind == Kind::AngleDeg ? "°" : "");
  return d.kind == Kind::Length ? text + " " + unit : text;
}

std::string boundsText(const SynthesisReport& r) {
  std::string text = "transmission angle >= " + formatShort(r.minTransmissionDeg) +
                     "°, longest / shortest link <= " + formatShort(r.maxLinkRatio);
  if (r.maxLink) text += ", no link longer than " + formatShort(*r.maxLink) + " " + r.lengthUnit;
  return text;
}

}  // namespace

void writeReportText(const SynthesisReport& r, std::size_t chosen, std::ostream& out) {
  out << "synthesize " << problemName(r.problem) << ": " << r.summary << "\n";
  out << "bounds: " << boundsText(r) << "\n";
  if (r.errorName.empty()) out << "error: none, the construction is exact\n";
  else out << "error: " << r.errorName << " (" << r.errorUnit << ")\n";
  out << "\n";
  writeTable(tableOf(r, chosen), out);
  out << "\nbest: #" << (r.best + 1) << ", " << r.bestRule << "\n";
  bool anyDefect = false;
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    for (const k::Defect& d : r.rows[i].candidate.defects) {
      if (!anyDefect) out << "defects (kept and marked, not dropped):\n";
      anyDefect = true;
      out << "  #" << (i + 1) << " " << k::toString(d.kind) << ": " << d.message << "\n";
    }
  if (!anyDefect) out << "defects: none\n";

  const CandidateRow& row = r.rows[chosen];
  out << "\nchosen: #" << (chosen + 1) << (chosen == r.best ? " (the best)" : "") << "\n";
  std::vector<std::pair<std::string, std::string>> lines;
  for (const auto& [name, value] : row.dimensions) lines.push_back({name, formatShort(value, 9) + " " + r.lengthUnit});
  lines.push_back({"Grashof class", grashofName(row.candidate)});
  lines.push_back({"min transmission angle", formatFixed(k::radToDeg(row.candidate.minTransmission), 4) + "°"});
  if (!r.errorName.empty())
    lines.push_back({r.errorName, formatShort(row.candidate.error * r.errorFactor) + " " + r.errorUnit});
  for (const SynthesisDetail& d : row.details) lines.push_back({d.label, detailText(d, r.lengthUnit)});
  std::size_t width = 0;
  for (const auto& [label, value] : lines) width = std::max(width, length(label));
  for (const auto& [label, value] : lines)
    out << "  " << label << std::string(width - length(label) + 2, ' ') << value << "\n";
}

void writeReportJson(const SynthesisReport& r, std::size_t chosen, const std::optional<std::string>& document,
                     std::ostream& out) {
  using k::io::jsonQuote;
  out << "{\n  \"problem\": \"" << problemName(r.problem) << "\",\n  \"summary\": " << jsonQuote(r.summary)
      << ",\n  \"length_unit\": " << jsonQuote(r.lengthUnit)
      << ",\n  \"bounds\": {\"min_transmission_deg\": " << formatJsonNumber(r.minTransmissionDeg)
      << ", \"max_link\": " << (r.maxLink ? formatJsonNumber(*r.maxLink) : "null")
      << ", \"max_link_ratio\": " << formatJsonNumber(r.maxLinkRatio) << "},\n  \"error\": ";
  if (r.errorName.empty()) out << "null";
  else out << "{\"name\": " << jsonQuote(r.errorName) << ", \"unit\": " << jsonQuote(r.errorUnit) << "}";
  out << ",\n  \"best\": " << (r.best + 1) << ",\n  \"chosen\": " << (chosen + 1) << ",\n  \"candidates\": [";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const CandidateRow& row = r.rows[i];
    const k::SynthesisCandidate& c = row.candidate;
    out << (i ? "," : "") << "\n    {\"index\": " << (i + 1);
    if (row.parameter) out << ", \"parameter\": " << formatJsonNumber(*row.parameter);
    out << ", \"lengths\": {";
    for (std::size_t j = 0; j < row.dimensions.size(); ++j)
      out << (j ? ", " : "") << jsonQuote(row.dimensions[j].first) << ": "
          << formatJsonNumber(row.dimensions[j].second);
    out << "}, \"error\": " << formatJsonNumber(c.error * r.errorFactor)
        << ", \"grashof\": " << (c.grashof ? jsonQuote(k::toString(c.grashof->category)) : "null")
        << ", \"min_transmission_deg\": " << formatJsonNumber(k::radToDeg(c.minTransmission)) << ", \"defects\": [";
    for (std::size_t j = 0; j < c.defects.size(); ++j)
      out << (j ? ", " : "") << "{\"kind\": \"" << k::toString(c.defects[j].kind)
          << "\", \"message\": " << jsonQuote(c.defects[j].message) << "}";
    out << "]}";
  }
  out << "\n  ],\n  \"chosen_details\": {";
  const auto& details = r.rows[chosen].details;
  for (std::size_t j = 0; j < details.size(); ++j) {
    const SynthesisDetail& d = details[j];
    out << (j ? "," : "") << "\n    " << jsonQuote(d.key) << ": ";
    if (d.kind == Kind::Text) out << jsonQuote(d.text);
    else if (d.values.size() == 1) out << formatJsonNumber(d.values[0]);
    else {
      out << "[";
      for (std::size_t v = 0; v < d.values.size(); ++v) out << (v ? ", " : "") << formatJsonNumber(d.values[v]);
      out << "]";
    }
  }
  out << "\n  },\n  \"document\": " << (document ? jsonQuote(*document) : "null") << "\n}\n";
}

}  // namespace linkwright::cli
