// linkwright-cli: the headless front end of the kinematics core (see --help).
#include "app/cli/cli.h"

#include "kinematics/io/safe_file.h"

#include <csignal>
#include <iostream>

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  // Past a file-size limit the kernel would kill the process mid-write, leaving the one
  // writer's temporary file behind; ignored, the write fails with EFBIG and is reported and
  // cleaned up like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  // Ctrl+C, SIGTERM or SIGHUP during a write removes its temporary file, then ends as the
  // signal would.
  linkwright::kinematics::io::removeTemporaryFilesOnSignals();
  const std::vector<std::string> args(argv + 1, argv + argc);
  return linkwright::cli::runCli(args, std::cout, std::cerr);
}
