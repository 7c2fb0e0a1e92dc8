#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/experiment/experiment_args.h"

namespace hexplore::experiment {
namespace {

ExperimentArgs parse(std::vector<std::string> args) {
  args.insert(args.begin(), "hexplore_experiment");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return parse_experiment_args(static_cast<int>(argv.size()), argv.data());
}

TEST(ExperimentArgs, SeedListsAndRanges) {
  EXPECT_EQ(parse_seed_list("3"), (std::vector<uint64_t>{3}));
  EXPECT_EQ(parse_seed_list("1,2,5-7"), (std::vector<uint64_t>{1, 2, 5, 6, 7}));
  EXPECT_EQ(parse_seed_list("0-0,9"), (std::vector<uint64_t>{0, 9}));
}

TEST(ExperimentArgs, BadSeedsAreNamed) {
  for (const char* bad : {"", "x", "1,,y", "-3", "5-2", "1-5000", "2.5"}) {
    try {
      parse_seed_list(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--seeds"), std::string::npos) << e.what();
    }
  }
}

TEST(ExperimentArgs, OptionsAndPassThrough) {
  const auto a = parse({"--config", "t.yaml", "--seeds", "1-3", "--planner", "no-mnss", "--robot", "r1", "--robot",
                        "r2", "--snapshot-period-s", "5", "--results", "out"});
  EXPECT_EQ(a.config, "t.yaml");
  EXPECT_EQ(a.seeds.size(), 3u);
  EXPECT_EQ(a.planner, "no-mnss");
  EXPECT_EQ(a.robots, (std::vector<std::string>{"r1", "r2"}));
  EXPECT_EQ(a.results_dir, "out");
  EXPECT_EQ(a.service_arguments.at("snapshot-period-s"), "5");
}

TEST(ExperimentArgs, TheComparison) {
  const auto a = parse({"--config", "t.yaml", "--seeds", "1,2", "--planners", "hexplore,mdvrp+,,tspga+", "--jobs", "3",
                        "--report", "false", "--report-script", "r.py"});
  EXPECT_EQ(a.planners, (std::vector<std::string>{"hexplore", "mdvrp+", "tspga+"}));
  EXPECT_FALSE(a.planner.has_value());
  EXPECT_EQ(a.jobs, 3);
  EXPECT_FALSE(a.report);
  EXPECT_EQ(a.report_script, "r.py");
  const auto d = parse({"--config", "t.yaml", "--seeds", "1", "--planners", "no-mnss"});
  EXPECT_EQ(d.jobs, 1);
  EXPECT_TRUE(d.report);
  EXPECT_FALSE(d.report_script.has_value());
  EXPECT_EQ(parse_planner_list("a,b"), (std::vector<std::string>{"a", "b"}));
}

TEST(ExperimentArgs, BadComparisonsAreNamed) {
  auto message = [](std::vector<std::string> args) {
    try {
      parse(std::move(args));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({"--config", "t", "--seeds", "1", "--planners", "a,b,a"}).find("listed twice"), std::string::npos);
  EXPECT_NE(message({"--config", "t", "--seeds", "1", "--planners", ","}).find("--planners"), std::string::npos);
  EXPECT_NE(message({"--config", "t", "--seeds", "1", "--planners", "a", "--planner", "b"}).find("exclude"),
            std::string::npos);
  for (const char* jobs : {"0", "x", "2.5", "65", "-1"})
    EXPECT_NE(message({"--config", "t", "--seeds", "1", "--planners", "a", "--jobs", jobs}).find("--jobs"), std::string::npos)
        << jobs;
  EXPECT_NE(message({"--config", "t", "--seeds", "1", "--report", "yes"}).find("--report"), std::string::npos);
}

// --out for --results once ran a whole mission, its results in the default folder.
TEST(ExperimentArgs, AnOptionNoServiceReadsIsRefusedWithTheNearestName) {
  try {
    parse({"--config", "t.yaml", "--seeds", "1", "--out", "dir"});
    ADD_FAILURE() << "accepted --out";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--out is no service's option"), std::string::npos) << e.what();
  }
  try {
    parse({"--config", "t.yaml", "--seeds", "1", "--trace-dri", "T"});
    ADD_FAILURE() << "accepted --trace-dri";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean --trace-dir?"), std::string::npos) << e.what();
  }
}

TEST(ExperimentArgs, MissingPiecesAreErrors) {
  EXPECT_THROW(parse({"--seeds", "1"}), std::invalid_argument);
  EXPECT_THROW(parse({"--config", "t.yaml"}), std::invalid_argument);
  EXPECT_THROW(parse({"--config"}), std::invalid_argument);
  EXPECT_THROW(parse({"config", "t.yaml"}), std::invalid_argument);
}

TEST(ExperimentArgs, HelpAsksForTheUsageAndNeedsNothingElse) {
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"-h"}).help);
  EXPECT_TRUE(parse({"--config", "t.yaml", "--help"}).help);
  EXPECT_FALSE(parse({"--config", "t.yaml", "--seeds", "1"}).help);
}

TEST(ExperimentArgs, TimeLimitOverridesTheTeamFilesAndRejectsNonsense) {
  EXPECT_FALSE(parse({"--config", "t.yaml", "--seeds", "1"}).time_limit_s.has_value());
  EXPECT_EQ(parse({"--config", "t.yaml", "--seeds", "1", "--time-limit-s", "5400"}).time_limit_s, 5400.0);
  for (const char* bad : {"0", "-5", "nan", "inf", "10s", "", "2e6"}) {
    try {
      parse({"--config", "t.yaml", "--seeds", "1", "--time-limit-s", bad});
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--time-limit-s"), std::string::npos) << e.what();
    }
  }
}

TEST(ExperimentArgs, ASweepIsEmittedOrGathered) {
  const auto emit = parse({"--config", "t.yaml", "--seeds", "1-2", "--planners", "a,b", "--emit-slurm", "sweep"});
  EXPECT_EQ(emit.emit_slurm, "sweep");
  const auto gather = parse({"--gather", "sweep"});
  EXPECT_EQ(gather.gather, "sweep");
  // The sweep folder holds the team file and seeds; given again they could disagree with it.
  EXPECT_THROW(parse({"--gather", "sweep", "--config", "t.yaml"}), std::invalid_argument);
  EXPECT_THROW(parse({"--gather", "sweep", "--seeds", "1"}), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::experiment
