#pragma once
// The lab report as a PDF (cairo's PDF surface: vector drawing, text as real glyphs that can be
// selected and searched). Pages in order: the title, the drawing and the analysis; the table;
// the extremes and the forces; the plots; each page numbered "page i of N". The content comes
// from report_content.h; this file only lays it out. One call serves the CLI's `report`
// command and the designer's Report ▸ PDF, so both write the same file.

#include "kinematics/model/result.h"
#include "kinematics/report/report_content.h"

#include <optional>
#include <string>
#include <string_view>

namespace linkwright::kinematics::report {

enum class Paper { A4, Letter };

/// "a4" or "letter" (lower case, as the CLI's --paper takes them); nullopt otherwise.
std::optional<Paper> paperFromName(std::string_view name);

/// Writes `report` on `paper` to `path`, whole or not at all (a temporary file next to it,
/// renamed over it). Fails with field "output", naming the path and the reason, when the file
/// cannot be written.
std::optional<Error> writeReportPdf(const ReportContent& report, Paper paper, const std::string& path);

}  // namespace linkwright::kinematics::report
