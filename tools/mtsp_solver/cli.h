#pragma once
// Command line of hexplore_mtsp: parsing into options and running one solve, printing the
// routes and objective. Split from main() so tests can drive it.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace hexplore::mtsp {

struct CliOptions {
  std::string tsp_file;
  int salesmen = 1;
  std::vector<int> depots;            // TSPLIB node ids, one per salesman (or one for all)
  bool closed = true;
  bool rounded = true;
  std::string species_file;
  std::string objective = "min-sum";  // min-sum | min-max | weighted
  double beta_c = 1.0, beta_m = 1.5;  // weighted objective
  double time_limit_s = 1.0;
  int generations = 0;                // 0 = only the time limit bounds the run
  int population = 64;
  uint64_t seed = 1;
  std::string local_search = "offspring";  // none | final | memetic | offspring
  bool inversion = true;
  int min_cities = 1;
  bool help = false;
};

// Throws std::invalid_argument naming the bad flag.
CliOptions parse_cli(const std::vector<std::string>& args);
std::string usage();
// Solves and prints; returns the process exit code. Errors go to `err` as one line.
int run_cli(const CliOptions& options, std::ostream& out, std::ostream& err);

}  // namespace hexplore::mtsp
