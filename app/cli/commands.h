#pragma once
// The three commands behind linkwright-cli: analyze (CSV table), classify (Grashof class,
// transmission angle, limit positions, assemblable range) and examples (the built-ins).

#include "app/cli/arguments.h"
#include "app/cli/exit_codes.h"

#include <iosfwd>

namespace linkwright::cli {

ExitCode runAnalyze(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runClassify(const Invocation& invocation, std::ostream& out, std::ostream& err);
ExitCode runExamples(std::ostream& out);

/// The four-bar an invocation describes: its --fourbar lengths or --example, with --unit,
/// --branch and --coupler-point applied.
struct ResolvedFourBar {
  kinematics::FourBarLengths lengths;
  std::string lengthUnit;
  kinematics::Branch branch = kinematics::Branch::Open;
  std::optional<kinematics::FourBarExample> example;
};
kinematics::Result<ResolvedFourBar> resolveFourBar(const Invocation& invocation);

} // namespace linkwright::cli
