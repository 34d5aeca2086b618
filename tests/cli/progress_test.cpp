// Progress on the error stream (app/cli/progress.h): drawn in place for a person at a
// terminal and cleared at the end; nothing at all for a pipe, a log or a test's stream, so a
// script sees the same bytes with or without it.

#include "app/cli/progress.h"
#include "tests/cli/run_cli.h"

#include "tests/support/catch.h"

#include <sstream>

using namespace linkwright;

TEST_CASE("progress is drawn in place and cleared, only where it is shown", "[cli][progress]") {
  std::ostringstream terminal;
  {
    cli::Progress progress(terminal, "analyze", "samples", true, std::chrono::milliseconds(0));
    progress.update(4500000, 10000000);
  }
  const std::string line = "analyze: 45 % (4500000 of 10000000 samples)";
  CHECK(terminal.str() == "\r" + line + "\r" + std::string(line.size(), ' ') + "\r");
  // Cleared for output to the same terminal, and drawn again at the next update.
  std::ostringstream cleared;
  {
    cli::Progress progress(cleared, "atlas", "cells", true, std::chrono::milliseconds(0));
    progress.update(1, 4);
    progress.clear();
    cleared << "row\n";
    progress.update(2, 4);
  }
  const std::string one = "atlas: 25 % (1 of 4 cells)", two = "atlas: 50 % (2 of 4 cells)";
  CHECK(cleared.str() == "\r" + one + "\r" + std::string(one.size(), ' ') + "\rrow\n\r" + two + "\r" +
                             std::string(two.size(), ' ') + "\r");
  // Not a terminal: nothing, before or after the first second.
  std::ostringstream pipe;
  {
    cli::Progress progress(pipe, "analyze", "samples");
    progress.update(1, 2);
  }
  CHECK(pipe.str().empty());
  CHECK_FALSE(cli::isTerminal(pipe));
  // Within its first second nothing is drawn: short work stays silent.
  std::ostringstream quick;
  {
    cli::Progress progress(quick, "extremes", "samples", true);
    progress.update(1, 2);
  }
  CHECK(quick.str().empty());
  // A long analyze into a test's stream writes its notes only.
  const test::CliRun run = test::runCliCommand({"analyze", "--example", "watt-ii", "--samples", "20000"});
  CHECK(run.code == 0);
  CHECK(run.err.empty());
}

TEST_CASE("progress is not drawn over output on the same terminal, nor where stderr is no terminal",
          "[cli][progress]") {
  std::ostringstream err, out;
  CHECK_FALSE(cli::progressShown(err, &out));
  CHECK_FALSE(cli::progressShown(err, nullptr));
}
