// What running a whole team needed from the planner: a bounded exploration region, views
// only where some robot can drive, given-up targets, and paths around blocked vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "common/core/team_config.h"
#include "common/planning/executable_path.h"
#include "common/planning/hexplore_planner.h"
#include "common/planning/planner_registry.h"
#include "common/planning/robot_vertex.h"
#include "common/planning/round_inputs.h"

#include "tests/support/planning_scene.h"

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
  PlanResult plan(const PlannerOptions& o, const GiveUpLedger* given_up = nullptr) const {
    auto p = PlannerRegistry::builtin().create("hexplore");
    p->configure({caps, o});
    PlanRequest r;
    r.map = &map;
    for (const auto& rc : team.robots) r.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
    r.given_up = given_up;
    return p->plan(r);
  }
};

// A perturbation study changes the planners' random stream alone (team_config.h).
TEST(PlannerOptions, PlannerSeedReplacesTheTeamSeedOnlyWhenSet) {
  core::AlgorithmParams p;
  p.seed = 5;
  EXPECT_EQ(PlannerOptions::from(p).seed, 5u);
  p.planner_seed = 1000008;
  EXPECT_EQ(PlannerOptions::from(p).seed, 1000008u);
}

TEST(TeamRun, TargetsStayInsideTheExplorationRegionViewsInsideTheStandRegion) {
  const Team t;
  const PlanResult all = t.plan(t.options);
  ASSERT_GT(all.views, 0);
  EXPECT_EQ(all.open_views, all.views);  // every cluster is served by someone here
  // The region's south edge runs just in front of the building's south facade (y = 5): seeing
  // the facade within gamma_th takes a standoff the region does not have.
  PlannerOptions half = t.options;
  half.region = Eigen::AlignedBox3d(Eigen::Vector3d(-1, 4.5, -0.5), Eigen::Vector3d(25, 17, 4.5));
  const PlanResult bounded = t.plan(half);
  EXPECT_LT(bounded.views, all.views);
  EXPECT_GT(bounded.view_stats.outside_region, 0);
  const Eigen::AlignedBox3d stand = stand_region(half.region, t.caps.max_observation_range());
  int outside = 0;
  for (const auto& r : bounded.robots)
    for (const auto& v : r.route) {
      EXPECT_TRUE(stand.contains(v.position));
      outside += half.region.contains(v.position) ? 0 : 1;
      for (uint64_t k : v.targets) EXPECT_TRUE(half.region.contains(t.map.find(k)->center)) << k;
    }
  EXPECT_GT(outside, 0);  // some views stand beyond the region's edge, looking back in
  PlannerOptions none = t.options;
  none.region = Eigen::AlignedBox3d(Eigen::Vector3d(100, 100, 100), Eigen::Vector3d(101, 101, 101));
  const PlanResult empty = t.plan(none);
  EXPECT_EQ(empty.views, 0);
  EXPECT_EQ(empty.open_views, 0);
}

TEST(TeamRun, TheStandRegionWidensTheRegionByItsHeightAtMostTheRange) {
  const Eigen::AlignedBox3d site(Eigen::Vector3d(0, 0, -0.5), Eigen::Vector3d(10, 20, 4.5));
  const Eigen::AlignedBox3d wide = stand_region(site, 27.0);
  EXPECT_TRUE(wide.min().isApprox(Eigen::Vector3d(-5, -5, -0.5)));
  EXPECT_TRUE(wide.max().isApprox(Eigen::Vector3d(15, 25, 4.5)));
  const Eigen::AlignedBox3d short_range = stand_region(site, 2.0);
  EXPECT_TRUE(short_range.min().isApprox(Eigen::Vector3d(-2, -2, -0.5)));
  const Eigen::AlignedBox3d open = stand_region(PlannerOptions::unbounded(), 27.0);
  EXPECT_FALSE(std::isfinite(open.max().x()));
}

TEST(TeamRun, GivenUpTargetsGetNoView) {
  const Team t;
  const PlanResult first = t.plan(t.options);
  std::unordered_set<uint64_t> ignored;
  GiveUpLedger ledger;
  for (const auto& r : first.robots)
    for (const auto& v : r.route) ignored.insert(v.targets.begin(), v.targets.end());
  ASSERT_FALSE(ignored.empty());
  for (uint64_t k : ignored) ledger.merge(k, t.map.find(k) ? t.map.find(k)->voxel_count : 0);
  const PlanResult again = t.plan(t.options, &ledger);
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

// A hall 4 m wide along +x (walls at y = 0 and y = 4, their facades centred on the surface as
// mapped), ground supervoxels every metre from y = 0.5, 8-connected.
highlevel::MapUpdate wall_hall() {
  using highlevel::SurfaceClass;
  highlevel::MapUpdate u;
  auto key = [](int i, int j) { return highlevel::supervoxel_key({i, j, 0}, SurfaceClass::kGround); };
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 4; ++j) {
      highlevel::Supervoxel g;
      g.key = key(i, j);
      g.center = {i + 0.5, j + 0.5, 0.0};
      g.surface = SurfaceClass::kGround;
      g.traversal_requirement = 1;
      g.voxel_count = 40;
      u.upserts.push_back(g);
      for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}, std::pair{1, -1}})
        if (i + di < 12 && j + dj >= 0 && j + dj < 4) u.edge_upserts.push_back(highlevel::EdgeKey::of(g.key, key(i + di, j + dj)));
    }
    for (int side = 0; side < 2; ++side) {
      highlevel::Supervoxel f;
      f.key = highlevel::supervoxel_key({i, side == 0 ? -1 : 4, 0}, SurfaceClass::kFacade);
      f.center = {i + 0.5, side == 0 ? 0.0 : 4.0, 0.5};
      f.normal = {0.0, side == 0 ? 1.0 : -1.0, 0.0};
      f.surface = SurfaceClass::kFacade;
      f.voxel_count = 40;
      u.upserts.push_back(f);
    }
  }
  return u;
}

// Paths keep the body clear of walls where the map has room (common/highlevel/clearance.h):
// with the species' body radius on the map, a path along a wall passes through waypoints at
// least that far from it, also when it goes around an avoided vertex. Without, the shortest
// path hugs the wall closer than the body's half-diagonal (what pinned robots in the main job).
TEST(TeamRun, PathsKeepTheBodyClearOfWalls) {
  const core::TeamConfig team = Team::make_team();
  highlevel::ClearanceOptions clearance;
  clearance.body_radius_m = highlevel::body_radii(team);
  highlevel::HighLevelMap plain_map(highlevel::species_levels(team));
  highlevel::HighLevelMap map(highlevel::species_levels(team), clearance);
  plain_map.apply(wall_hall());
  map.apply(wall_hall());
  highlevel::ClearanceIndex walls(clearance);
  for (const auto& [key, sv] : map.supervoxels()) walls.insert(sv);
  auto tightest = [&](const ExecutablePlan& p) {
    double m = 10.0;
    for (const auto& w : p.waypoints) m = std::min(m, walls.clearance(w, 10.0));
    return m;
  };
  for (int species = 0; species < 2; ++species) {
    const double radius = clearance.body_radius_m[size_t(species)];
    TaskView goal;
    goal.ground_key = highlevel::supervoxel_key({11, 0, 0}, highlevel::SurfaceClass::kGround);
    const Eigen::Vector3d from(0.5, 0.5, 0);
    const ExecutablePlan plain = executable_path(plain_map.graph(), from, species, goal);
    const ExecutablePlan clear = executable_path(map.graph(), from, species, goal);
    ASSERT_TRUE(plain.valid);
    ASSERT_TRUE(clear.valid);
    EXPECT_LT(tightest(plain), radius) << species;
    EXPECT_GE(tightest(clear), radius - 1e-6) << species;
    std::unordered_set<uint64_t> avoid{clear.keys[clear.keys.size() / 2]};
    const ExecutablePlan around = executable_path(map.graph(), from, species, goal, &avoid);
    ASSERT_TRUE(around.valid);
    EXPECT_GE(tightest(around), radius - 1e-6) << species;
  }
}

// Views do not stand where the body has no room (here: under a vehicle roof): the robots
// drove there, were blocked by the vehicle's body and came back for the next target there.
TEST(TeamRun, NoViewStandsWhereTheBodyHasNoRoom) {
  const Team t;
  highlevel::HighLevelMap map(highlevel::species_levels(t.team), highlevel::clearance_options(t.team));
  highlevel::MapUpdate u = wall_hall();
  for (auto& sv : u.upserts) sv.covered = sv.facade();  // all ground still to be seen
  highlevel::Supervoxel roof;
  roof.key = highlevel::supervoxel_key({6, 2, 1}, highlevel::SurfaceClass::kFacade);
  roof.center = {6.5, 2.5, 1.2};
  roof.normal = {0, 0, 1};
  roof.surface = highlevel::SurfaceClass::kFacade;
  roof.covered = true;
  u.upserts.push_back(roof);
  map.apply(u);
  const uint64_t under = highlevel::supervoxel_key({6, 2, 0}, highlevel::SurfaceClass::kGround);
  ASSERT_FALSE(map.graph().room_to_stand(under, 0));
  auto p = PlannerRegistry::builtin().create("hexplore");
  p->configure({t.caps, t.options});
  PlanRequest r;
  r.map = &map;
  r.robots = {{"slug1", 0, {0.5, 1.5, 0}}, {"mr1", 1, {11.5, 2.5, 0}}};
  const PlanResult res = p->plan(r);
  ASSERT_GT(res.views, 0);
  EXPECT_GT(res.view_stats.unreachable_ground, 0);
  for (const auto& plan : res.robots)
    for (const auto& v : plan.route) EXPECT_NE(v.ground_key, under);
}

}  // namespace
}  // namespace hexplore::planning
