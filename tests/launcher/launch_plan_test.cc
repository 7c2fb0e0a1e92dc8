#include "tools/launcher/launch_plan.h"

#include <gtest/gtest.h>

#include "common/core/team_config.h"

namespace hexplore::launcher {
namespace {

core::TeamConfig team() {
  return core::parse_team_config(
      "species: [{builtin: SLUGCAT}]\nrobots:\n  - {id: a, species: SLUGCAT}\n  - {id: b, species: SLUGCAT}\n",
      "team.yaml");
}

TEST(LaunchPlan, EveryServiceOfEveryRobotPlusStation) {
  LaunchRequest request;
  request.config_path = "team.yaml";
  request.bin_dirs = {FAKE_BIN_DIR};
  const auto plan = plan_launch(team(), request, "/nowhere/hexplore_launch");
  EXPECT_TRUE(plan.missing.empty());
  ASSERT_EQ(plan.processes.size(), 11u);
  EXPECT_EQ(plan.processes[0].name, "a/sim");
  EXPECT_EQ(plan.processes[4].name, "a/safety");
  EXPECT_EQ(plan.processes[9].name, "b/safety");
  EXPECT_TRUE(plan.processes[10].is_station);
  EXPECT_EQ(plan.processes[3].arguments, (std::vector<std::string>{"--config", "team.yaml", "--robot", "a"}));
  EXPECT_EQ(plan.processes[10].arguments, (std::vector<std::string>{"--config", "team.yaml"}));
}

TEST(LaunchPlan, StationIsOptionalUnlessAskedFor) {
  LaunchRequest request;
  request.config_path = "team.yaml";
  request.bin_dirs = {"/nonexistent"};
  const auto plan = plan_launch(team(), request, "/nowhere/hexplore_launch");
  EXPECT_EQ(plan.processes.size(), 10u);
  EXPECT_EQ(plan.missing.size(), 10u);
  request.services = {"station"};
  EXPECT_EQ(plan_launch(team(), request, "/nowhere/hexplore_launch").missing.size(), 1u);
}

TEST(LaunchPlan, FiltersAndErrors) {
  LaunchRequest request;
  request.config_path = "team.yaml";
  request.bin_dirs = {FAKE_BIN_DIR};
  request.robots = {"b"};
  request.services = {"sim", "safety"};
  const auto plan = plan_launch(team(), request, "x");
  ASSERT_EQ(plan.processes.size(), 2u);
  EXPECT_EQ(plan.processes[1].name, "b/safety");
  request.robots = {"c"};
  EXPECT_THROW(plan_launch(team(), request, "x"), std::invalid_argument);
  EXPECT_EQ(split_list("a,,b"), (std::vector<std::string>{"a", "b"}));
}

TEST(LaunchPlan, DefaultSearchFoldersFollowTheBuildTree) {
  const auto dirs = default_bin_dirs("/build/tools/launcher/hexplore_launch", "sim");
  ASSERT_EQ(dirs.size(), 2u);
  EXPECT_EQ(dirs[0], "/build/tools/launcher");
  EXPECT_EQ(dirs[1], "/build/services/sim");
}

}  // namespace
}  // namespace hexplore::launcher
