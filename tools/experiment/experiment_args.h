#pragma once
// Command line of hexplore_experiment.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hexplore::experiment {

struct ExperimentArgs {
  std::string config;
  std::vector<uint64_t> seeds;         // --seeds 1,2,5-8
  std::string results_dir = "results/experiment";
  std::optional<std::string> planner;  // overrides params.planner
  std::vector<std::string> robots;     // empty: every robot of the team file
  std::string log_level = "warn";
  std::map<std::string, std::string> service_arguments;  // any other --name value
};

// Throws std::invalid_argument with a one-line message.
ExperimentArgs parse_experiment_args(int argc, char** argv);
// "1,2,5-8" -> {1, 2, 5, 6, 7, 8}; throws std::invalid_argument.
std::vector<uint64_t> parse_seed_list(const std::string& text);

}  // namespace hexplore::experiment
