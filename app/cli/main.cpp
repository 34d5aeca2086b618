// linkwright-cli: the headless front end of the kinematics core (see --help).
#include "app/cli/cli.h"

#include <iostream>

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  const std::vector<std::string> args(argv + 1, argv + argc);
  return linkwright::cli::runCli(args, std::cout, std::cerr);
}
