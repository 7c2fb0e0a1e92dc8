// hexplore_mtsp: command-line HMDMTSP solver (see --help).
#include <iostream>

#include "tools/mtsp_solver/cli.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  hexplore::mtsp::CliOptions options;
  try {
    options = hexplore::mtsp::parse_cli(args);
  } catch (const std::exception& e) {
    std::cerr << "hexplore_mtsp: " << e.what() << "\n";
    return 2;
  }
  return hexplore::mtsp::run_cli(options, std::cout, std::cerr);
}
