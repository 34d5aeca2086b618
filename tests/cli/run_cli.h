#pragma once
// Runs linkwright-cli in-process (runCli) and keeps its exit code and both output streams.

#include "app/cli/cli.h"

#include <sstream>
#include <string>
#include <vector>

namespace linkwright::test {

struct CliRun {
  int code = -1;
  std::string out;
  std::string err;
};

inline CliRun runCliCommand(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  CliRun r;
  r.code = cli::runCli(args, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace linkwright::test
