// What running a whole team needed from the planner: a bounded exploration region, views
// only where some robot can drive, given-up targets, and paths around blocked vertices.
#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/planning/hexplore_planner.h"
#include "common/planning/planner_registry.h"
#include "common/planning/robot_vertex.h"
#include "common/planning/synthetic_scene.h"

namespace hexplore::planning {
namespace {

struct Team {
  core::TeamConfig team;
  TeamCapabilities caps;
  PlannerOptions options;
  highlevel::HighLevelMap map;
  Team() : team(make_team()), caps(capabilities_from(team)), map(highlevel::species_levels(team)) {
    options = PlannerOptions::from(team.params);
    options.ga_time_budget_s = 0.0;
    options.ga_max_generations = 100;
    SyntheticSceneOptions s;
    s.width_cells = 24;
    s.depth_cells = 16;
    s.buildings = {{5, 5, 12, 11, 4}};
    s.covered_fraction = 0.2;
    map.apply(synthetic_scene(s));
  }
  static core::TeamConfig make_team() {
    core::TeamConfig t;
    t.species = {core::builtin_slugcat(), core::builtin_mr1000()};
    t.robots = {{"slug1", "SLUGCAT", {1.5, 1.5, 0}, 0}, {"mr1", "MR1000", {20.5, 1.5, 0}, 0}};
    return t;
  }
  PlanResult plan(const PlannerOptions& o, std::unordered_set<uint64_t> ignored = {}) const {
    auto p = PlannerRegistry::builtin().create("hexplore");
    p->configure({caps, o});
    PlanRequest r;
    r.map = &map;
    for (const auto& rc : team.robots) r.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
    r.ignored = std::move(ignored);
    return p->plan(r);
  }
};

TEST(TeamRun, ViewsStayInsideTheExplorationRegion) {
  const Team t;
  const PlanResult all = t.plan(t.options);
  ASSERT_GT(all.views, 0);
  EXPECT_EQ(all.open_views, all.views);  // every cluster is served by someone here
  PlannerOptions half = t.options;
  half.region = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(12, 17, 10));
  const PlanResult bounded = t.plan(half);
  EXPECT_LT(bounded.views, all.views);
  EXPECT_GT(bounded.view_stats.outside_region, 0);
  for (const auto& r : bounded.robots)
    for (const auto& v : r.route) EXPECT_TRUE(half.region.contains(v.position));
  PlannerOptions none = t.options;
  none.region = Eigen::AlignedBox3d(Eigen::Vector3d(100, 100, 100), Eigen::Vector3d(101, 101, 101));
  const PlanResult empty = t.plan(none);
  EXPECT_EQ(empty.views, 0);
  EXPECT_EQ(empty.open_views, 0);
}

TEST(TeamRun, GivenUpTargetsGetNoView) {
  const Team t;
  const PlanResult first = t.plan(t.options);
  std::unordered_set<uint64_t> ignored;
  for (const auto& r : first.robots)
    for (const auto& v : r.route) ignored.insert(v.targets.begin(), v.targets.end());
  ASSERT_FALSE(ignored.empty());
  const PlanResult again = t.plan(t.options, ignored);
  EXPECT_LT(again.views, first.views);
  EXPECT_GT(again.view_stats.ignored, 0);
  for (const auto& r : again.robots)
    for (const auto& v : r.route)
      for (uint64_t k : v.targets) EXPECT_FALSE(ignored.count(k)) << "view for given-up target " << k;
}

TEST(TeamRun, PathsGoAroundAvoidedVertices) {
  const Team t;
  const auto& graph = t.map.graph();
  const Eigen::Vector3d from(1.5, 1.5, 0);
  const auto goal_key = robot_vertex(graph, Eigen::Vector3d(20.5, 1.5, 0), 0);
  ASSERT_TRUE(goal_key);
  TaskView goal;
  goal.ground_key = *goal_key;
  const ExecutablePlan direct = executable_path(graph, from, 0, goal);
  ASSERT_TRUE(direct.valid);
  ASSERT_GE(direct.keys.size(), 4u);
  std::unordered_set<uint64_t> avoid{direct.keys[direct.keys.size() / 2]};
  const ExecutablePlan around = executable_path(graph, from, 0, goal, &avoid);
  ASSERT_TRUE(around.valid);
  for (uint64_t k : around.keys) EXPECT_FALSE(avoid.count(k));
  EXPECT_EQ(around.keys.back(), *goal_key);
  avoid.insert(*goal_key);
  EXPECT_FALSE(executable_path(graph, from, 0, goal, &avoid).valid);
}

}  // namespace
}  // namespace hexplore::planning
