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
  // --planners a,b,c: the comparison, each planner's seeds in results_dir/<planner>/, then the
  // report (results_dir/comparison.*); excludes --planner.
  std::vector<std::string> planners;
  // --time-limit-s S: replaces the team file's time_limit_s, e.g. to run the default team to its
  // end (the team file's limit bounds the main job) without editing the file.
  std::optional<double> time_limit_s;
  int jobs = 1;                        // --jobs N: up to N planners' runs at once, as child processes
  bool report = true;                  // --report false: no figures, no comparison report
  std::optional<std::string> report_script;  // --report-script PATH (default: the source tree's)
  std::vector<std::string> robots;     // empty: every robot of the team file
  std::string log_level = "warn";
  std::map<std::string, std::string> service_arguments;  // any other --name value
  bool help = false;                   // --help or -h: print the usage and stop
  // --emit-slurm DIR: write the runs as a Slurm job array into DIR instead of running them.
  std::optional<std::string> emit_slurm;
  // --gather DIR: the comparison of what a sweep's array tasks wrote (needs nothing else).
  std::optional<std::string> gather;
};

// Throws std::invalid_argument with a one-line message.
ExperimentArgs parse_experiment_args(int argc, char** argv);
// "1,2,5-8" -> {1, 2, 5, 6, 7, 8}; throws std::invalid_argument.
std::vector<uint64_t> parse_seed_list(const std::string& text);
// "a,b,c" -> {"a", "b", "c"}: non-empty, no name twice; throws std::invalid_argument.
std::vector<std::string> parse_planner_list(const std::string& text);

}  // namespace hexplore::experiment
