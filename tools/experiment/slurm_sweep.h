#pragma once
// A sweep of hexplore_experiment runs (planners x seeds of one team file) as a job array for a
// Slurm cluster, and the gathering of what the array wrote into one comparison.
//
//   hexplore_experiment --config T --seeds 1-5 --planners a,b --results R --emit-slurm DIR
//     writes DIR/runs.tsv (one line per run: array index, planner, seed) and DIR/sweep.sbatch;
//     `sbatch DIR/sweep.sbatch` runs each line as one array task: the same executable, one
//     planner, one seed, into R/<planner>/seed-<seed>/ (each task writes into a folder of its
//     own under R/.tasks/ and moves the seed folder in place when its run ended).
//   hexplore_experiment --gather DIR
//     checks that every run of DIR/runs.tsv left its summary, then writes R/planners.txt, each
//     planner's figures and the comparison (tools/report/run_report.py, compare_report.py), as
//     --planners on one machine does.

#include <cstdint>
#include <string>
#include <vector>

#include "tools/experiment/experiment_args.h"

namespace hexplore::experiment {

struct SweepRun {
  std::string planner;  // "" with neither --planner nor --planners: the team file's
  uint64_t seed = 0;
};

// Planner-major, in the order given: every seed of the first planner, then the next.
std::vector<SweepRun> sweep_runs(const ExperimentArgs& args);

// Quotes `text` for bash (single quotes; a quote inside becomes '\'').
std::string shell_quoted(const std::string& text);

// Writes DIR/runs.tsv and DIR/sweep.sbatch for `args` (results folder, time limit, robots, log
// level, service options; --trace-dir T becomes T/<planner>), run by `executable`. Paths are
// made absolute: array tasks may start anywhere. Throws std::runtime_error when DIR cannot be
// written. Returns the script's path.
std::string write_slurm_sweep(const ExperimentArgs& args, const std::string& executable, const std::string& dir);

// What a sweep folder (DIR of --emit-slurm) says about its runs.
struct SweepStatus {
  std::string results_dir;
  std::vector<std::string> planners;  // in runs.tsv's order, each once
  std::vector<SweepRun> done;         // runs whose seed folder holds a summary.json
  std::vector<SweepRun> missing;      // the others (failed, still running, never run)
};

// Reads DIR/runs.tsv and looks for each run's results. Throws std::runtime_error when runs.tsv
// is missing or malformed.
SweepStatus read_sweep(const std::string& dir);

}  // namespace hexplore::experiment
