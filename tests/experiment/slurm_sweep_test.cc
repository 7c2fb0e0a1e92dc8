// The Slurm sweep's files: which runs, the job script bash accepts, and what --gather finds.
// (A sweep run by a real single-node Slurm: run_slurm_sweep.sh.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/support/scratch_dir.h"
#include "tools/experiment/slurm_sweep.h"

namespace hexplore::experiment {
namespace {

namespace fs = std::filesystem;

ExperimentArgs two_planners(const fs::path& root) {
  ExperimentArgs args;
  args.config = "team.yaml";
  args.seeds = {3, 5};
  args.planners = {"hexplore", "mdvrp+"};
  args.results_dir = (root / "results").string();
  args.time_limit_s = 60.0;
  args.service_arguments["trace-dir"] = (root / "traces").string();
  args.service_arguments["end-settle-s"] = "7";
  return args;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SlurmSweep, EveryPlannerTimesEverySeedInOrder) {
  const auto runs = sweep_runs(two_planners("/x"));
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[1].planner, "hexplore");
  EXPECT_EQ(runs[1].seed, 5u);
  EXPECT_EQ(runs[2].planner, "mdvrp+");
  ExperimentArgs one;
  one.seeds = {1};
  EXPECT_EQ(sweep_runs(one)[0].planner, "");  // the team file's planner
}

TEST(SlurmSweep, QuotesSurviveTheShell) {
  EXPECT_EQ(shell_quoted("a b"), "'a b'");
  EXPECT_EQ(shell_quoted("it's"), "'it'\\''s'");
}

TEST(SlurmSweep, TheScriptIsAnArrayOfOneTaskPerRunAndBashAcceptsIt) {
  const hexplore::testing::ScratchDir scratch("slurm_sweep_test");
  const fs::path root(scratch.file("script"));
  const ExperimentArgs args = two_planners(root);
  const std::string script = write_slurm_sweep(args, "/opt/hexplore/hexplore_experiment", (root / "sweep").string());
  const std::string text = read(script);
  EXPECT_NE(text.find("#SBATCH --array=0-3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("--time-limit-s 60"), std::string::npos);
  EXPECT_NE(text.find("--end-settle-s '7'"), std::string::npos);
  EXPECT_NE(text.find("--trace-dir '" + (root / "traces").string() + "'\"${planner:+/$planner}\""), std::string::npos);
  EXPECT_EQ(std::system(("bash -n " + script).c_str()), 0);
  const std::string table = read(root / "sweep" / "runs.tsv");
  EXPECT_EQ(table, "results\t" + (root / "results").string() + "\nindex\tplanner\tseed\n0\thexplore\t3\n1\thexplore\t5\n"
                   "2\tmdvrp+\t3\n3\tmdvrp+\t5\n");
}

TEST(SlurmSweep, GatherTellsTheRunsThatLeftResultsFromTheMissing) {
  const hexplore::testing::ScratchDir scratch("slurm_sweep_test");
  const fs::path root(scratch.file("gather"));
  write_slurm_sweep(two_planners(root), "/bin/true", (root / "sweep").string());
  for (const char* done : {"hexplore/seed-3", "mdvrp+/seed-5"}) {
    fs::create_directories(root / "results" / done);
    std::ofstream(root / "results" / done / "summary.json") << "{}";
  }
  fs::create_directories(root / "results" / "hexplore" / "seed-5");  // a task that died mid-run
  const SweepStatus status = read_sweep((root / "sweep").string());
  EXPECT_EQ(status.planners, (std::vector<std::string>{"hexplore", "mdvrp+"}));
  ASSERT_EQ(status.done.size(), 2u);
  ASSERT_EQ(status.missing.size(), 2u);
  EXPECT_EQ(status.missing[0].planner, "hexplore");
  EXPECT_EQ(status.missing[0].seed, 5u);
}

TEST(SlurmSweep, ABrokenOrAbsentTableIsAnErrorThatSaysWhere) {
  const hexplore::testing::ScratchDir scratch("slurm_sweep_test");
  const fs::path root(scratch.file("broken"));
  EXPECT_THROW(read_sweep((root / "nothing").string()), std::runtime_error);
  fs::create_directories(root);
  std::ofstream(root / "runs.tsv") << "results\t/r\nindex\tplanner\tseed\n0\thexplore\tseven\n";
  try {
    read_sweep(root.string());
    FAIL() << "a seed that is no number was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("runs.tsv:3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hexplore::experiment
