// `linkwright-cli synthesize PROBLEM …`: solves the synthesis problem (kinematics/synthesis/),
// prints every candidate with its defects (text or JSON) and writes the chosen one as a
// Linkwright document that analyze, extremes and classify read.

#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/synthesize_report.h"

#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"

#include <ostream>

namespace linkwright::cli {

ExitCode runSynthesize(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const SynthesisRequest& request = *inv.synthesis;
  const auto report = [&] {
    Progress progress(err, "synthesize path", "starts");
    return solveSynthesis(request, [&progress](int done, int total) {
      progress.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    });
  }();
  if (!report) {
    err << "linkwright-cli: " << report.error().message << "\n";
    // A search that found nothing is not bad input: the targets may be fine, the starts too few.
    return report.error().code == kinematics::ErrorCode::NotAssemblable ? ExitCode::NotAssemblable : ExitCode::BadInput;
  }
  const std::size_t count = report->rows.size();
  if (request.choose && static_cast<std::size_t>(*request.choose) > count) {
    err << "linkwright-cli: --choose must be between 1 and " << count << " (the candidates listed; got "
        << *request.choose << ")\n";
    return ExitCode::BadInput;
  }
  const std::size_t chosen = request.choose ? static_cast<std::size_t>(*request.choose - 1) : report->best;
  const CandidateRow& row = report->rows[chosen];
  // Write first, so the JSON names a document that exists.
  if (request.outputFile) {
    // The document keeps what it was synthesised for: the designer shows the targets again.
    kinematics::Design design = row.candidate.design;
    design.synthesis = targetsOf(request);
    if (auto e = kinematics::io::writeFileSafely(*request.outputFile, kinematics::io::writeDocument(design))) {
      err << "linkwright-cli: " << e->message << "\n";
      return ExitCode::IoError;
    }
    if (!row.candidate.defects.empty()) {
      err << "linkwright-cli: note: candidate #" << (chosen + 1) << ", written to " << *request.outputFile
          << ", has defects:";
      for (const kinematics::Defect& d : row.candidate.defects) err << " " << kinematics::toString(d.kind) << ";";
      err << " see the list\n";
    }
  }
  if (request.json) writeReportJson(*report, chosen, request.outputFile, out);
  else {
    writeReportText(*report, chosen, out);
    if (request.outputFile) out << "\nwrote #" << (chosen + 1) << " to " << *request.outputFile << "\n";
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
