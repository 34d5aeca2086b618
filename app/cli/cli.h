#pragma once
// linkwright-cli as a function: the executable's main() and the tests both call runCli.

#include <iosfwd>
#include <string>
#include <vector>

namespace linkwright::cli {

/// Runs the command line `args` (without the program name); writes results to `out` and
/// messages to `err`; returns the exit code (see exit_codes.h).
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// The full --help text, or a command's help for topic "analyze" / "classify".
std::string helpText(const std::string& topic = {});

}  // namespace linkwright::cli
