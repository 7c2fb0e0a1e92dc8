#include "common/planning/mnss.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/planning/cluster_work.h"
#include "common/planning/cost_model.h"
#include "common/planning/round_inputs.h"
#include "common/highlevel/supervoxel.h"
#include "common/planning/frontier.h"
#include "common/planning/mtsp/mtsp_problem.h"
#include "common/planning/route_pruning.h"
#include "common/planning/visibility.h"

#include "tests/support/planning_scene.h"

namespace hexplore::planning {
namespace {

TaskView at(uint64_t key, double x) {
  TaskView v;
  v.key = key;
  v.position = {x, 0, 0};
  return v;
}

TEST(OrderViews, CheapestOpenPathBetweenVirtualEnds) {
  const std::vector<TaskView> views = {at(1, 4), at(2, 1), at(3, 3), at(4, 2)};
  const auto forward = order_views(views, {0, 0, 0}, Eigen::Vector3d(10, 0, 0));
  std::vector<uint64_t> keys;
  for (const auto& v : forward) keys.push_back(v.key);
  EXPECT_EQ(keys, (std::vector<uint64_t>{2, 4, 3, 1}));
  EXPECT_NEAR(tour_length(forward, {0, 0, 0}, Eigen::Vector3d(10, 0, 0)), 10.0, 1e-12);
  // Start at the far end: the order reverses.
  const auto backward = order_views(views, {5, 0, 0}, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(backward.front().key, 1u);
  EXPECT_EQ(backward.back().key, 2u);
}

// The team's two species on a 30 x 20 m ground grid with one 9 x 8 m building.
struct OneBuilding {
  core::TeamConfig team = [] {
    core::TeamConfig t;
    t.species = {core::builtin_slugcat(), core::builtin_mr1000()};
    return t;
  }();
  TeamCapabilities caps = capabilities_from(team);
  PlannerOptions o = PlannerOptions::from(team.params);
  highlevel::HighLevelMap map;
  // With clearance options the map is planning's: it knows the rim of the known ground.
  explicit OneBuilding(bool planning_map = false)
      : map(highlevel::species_levels(team), planning_map ? highlevel::clearance_options(team) : highlevel::ClearanceOptions{}) {
    SyntheticSceneOptions scene;
    scene.width_cells = 30;
    scene.depth_cells = 20;
    scene.buildings = {{5, 5, 14, 13, 5}};
    scene.rubble = {};
    map.apply(synthetic_scene(scene));
  }
};

TEST(Mnss, CoversEveryTargetWithFewerViews) {
  OneBuilding b;
  const TeamCapabilities& caps = b.caps;
  const PlannerOptions& o = b.o;
  highlevel::HighLevelMap& map = b.map;
  const MapContext ctx(map, o);
  const auto views = generate_task_views(ctx, caps, o);
  const auto clusters = cluster_views(views, o.eta_r_m);
  ASSERT_FALSE(clusters.empty());
  int total_before = 0, total_after = 0;
  for (const auto& cl : clusters) {
    if (cl.label != kPublic) continue;
    core::PlanRng rng(3);
    TourStats stats;
    const Eigen::Vector3d start = cl.center + Eigen::Vector3d(-8, 0, 0);
    const auto tour = mnss_tour(ctx, views, cl.views, {cl.center}, o.eta_r_m, caps.species[0], start, std::nullopt, o, rng,
                                &stats);
    std::set<uint64_t> wanted, got;
    for (int v : cl.views) wanted.insert(views[size_t(v)].targets.begin(), views[size_t(v)].targets.end());
    for (const auto& v : tour) {
      got.insert(v.targets.begin(), v.targets.end());
      const auto* g = map.find(v.ground_key);
      ASSERT_TRUE(g && g->passable_for_level(caps.species[0].traversal_level));
    }
    EXPECT_EQ(got, wanted) << "cluster " << cl.id;
    total_before += int(cl.views.size());
    total_after += int(tour.size());
    // Same seed, same tour.
    core::PlanRng again(3);
    const auto repeat = mnss_tour(ctx, views, cl.views, {cl.center}, o.eta_r_m, caps.species[0], start, std::nullopt, o, again);
    ASSERT_EQ(repeat.size(), tour.size());
    for (size_t i = 0; i < tour.size(); ++i) EXPECT_EQ(repeat[i].key, tour[i].key);
  }
  EXPECT_LT(total_after, total_before);
}

// The cover reading of delta (cluster_work.h): a cluster's targets are seen from a few of its
// views, so each species stands at fewer facade views than the cluster has, and the cost model
// charges much less than the paper's walk to and dwell at every view.
TEST(ClusterWork, TheCoverStandsAtFewerViewsThanTheClusterHas) {
  OneBuilding b;
  const MapContext ctx(b.map, b.o);
  const auto views = generate_task_views(ctx, b.caps, b.o);
  const auto clusters = cluster_views(views, b.o.eta_r_m);
  int facade_views = 0, dwells = 0;
  for (const auto& cl : clusters) {
    if (cl.label != kPublic) continue;
    for (const auto& species : b.caps.species) {
      const ClusterWork work = cover_work(ctx, views, cl, species, b.o);
      EXPECT_LE(work.dwells, std::max(1, cl.facade_views)) << "cluster " << cl.id;
      if (cl.facade_views > 0) {
        EXPECT_GE(work.dwells, 1) << "cluster " << cl.id;
      }
      EXPECT_GE(work.walk_m, 0.0);
      const ClusterWork again = cover_work(ctx, views, cl, species, b.o);
      EXPECT_EQ(again.dwells, work.dwells);
      EXPECT_EQ(again.walk_m, work.walk_m);
      facade_views += cl.facade_views;
      dwells += work.dwells;
    }
  }
  ASSERT_GT(facade_views, 0);
  EXPECT_LT(2 * dwells, facade_views);

  // The cost model: the same clusters and reachability, each execution time no more than half
  // the every-view one in total.
  std::vector<RobotState> robots(2);
  robots[0].species = 0;
  robots[0].position = {1, 1, 0};
  robots[1].species = 1;
  robots[1].position = {2, 1, 0};
  const auto& graph = b.map.graph();
  const auto vertices = robot_vertices(graph, robots, b.caps);
  const CoverReading cover{ctx, b.o};
  const AssignmentInstance literal = build_assignment(graph, views, clusters, b.caps, robots, vertices);
  const AssignmentInstance covered = build_assignment(graph, views, clusters, b.caps, robots, vertices, &cover);
  ASSERT_EQ(covered.city_cluster, literal.city_cluster);
  double sum_literal = 0.0, sum_cover = 0.0;
  for (size_t k = 0; k < literal.problem.execution.size(); ++k)
    for (size_t i = 0; i < literal.problem.execution[k].size(); ++i) {
      const double a = literal.problem.execution[k][i], c = covered.problem.execution[k][i];
      ASSERT_EQ(std::isfinite(a), std::isfinite(c));
      if (std::isfinite(a)) {
        sum_literal += a;
        sum_cover += c;
      }
    }
  EXPECT_LT(2 * sum_cover, sum_literal);
}

// A cluster of one view: the robot stands there, no walk inside the cluster.
TEST(ClusterWork, ASingleViewIsOneDwellAndNoWalk) {
  OneBuilding b;
  const MapContext ctx(b.map, b.o);
  const auto views = generate_task_views(ctx, b.caps, b.o);
  for (const auto& cl : singleton_clusters(views)) {
    if (cl.label != kPublic || cl.facade_views == 0) continue;
    const ClusterWork work = cover_work(ctx, views, cl, b.caps.species[1], b.o);
    EXPECT_EQ(work.dwells, 1);
    EXPECT_NEAR(work.walk_m, 0.0, 1e-9);
    return;
  }
  FAIL() << "no public facade view";
}

// Ground at the frontier of the known ground (here the synthetic grid's edge: the planning
// map's rim, the region unbounded) is seen only from its own vertex: every tour view that holds
// such a target stands on it and says so (`frontier`), so the robot drives onto the rim.
TEST(Mnss, GroundAtTheFrontierIsSeenOnlyFromItsOwnVertex) {
  OneBuilding b(/*planning_map=*/true);
  const highlevel::HighLevelMap& map = b.map;
  const MapContext ctx(map, b.o);
  const auto views = generate_task_views(ctx, b.caps, b.o);
  const auto clusters = cluster_views(views, b.o.eta_r_m);
  int frontier_targets = 0;
  for (const auto& cl : clusters) {
    if (cl.label != kPublic) continue;
    core::PlanRng rng(3);
    const auto tour = mnss_tour(ctx, views, cl.views, {cl.center}, b.o.eta_r_m, b.caps.species[0],
                                cl.center + Eigen::Vector3d(-8, 0, 0), std::nullopt, b.o, rng);
    for (const auto& v : tour)
      for (uint64_t t : v.targets) {
        const highlevel::Supervoxel* sv = map.find(t);
        if (!sv || sv->facade() || !at_frontier(map, *sv, b.o.region)) continue;
        ++frontier_targets;
        EXPECT_EQ(v.ground_key, t) << "a frontier target observed from another vertex";
        EXPECT_TRUE(v.frontier);
      }
  }
  EXPECT_GT(frontier_targets, 0);
  // The score itself: its own vertex sees it, the next one (a metre in) does not.
  for (const auto& [key, sv] : map.supervoxels()) {
    if (!sv.traversable() || !at_frontier(map, sv, b.o.region)) continue;
    EXPECT_GT(ground_target_score(map, sv, sv, b.o), 0.0);
    for (const auto& [other, length] : map.graph().neighbours(key))
      EXPECT_EQ(ground_target_score(map, *map.find(other), sv, b.o), 0.0);
    break;
  }
}

// With a shared-view margin, a spot stands in for another target's view only where it sees
// that target well inside the angle limits; a target no such spot sees keeps its own view.
TEST(Mnss, ASharedViewSeesItsTargetsInsideTheMargin) {
  OneBuilding b;
  b.o.shared_view_margin_deg = 15.0;
  const TeamCapabilities& caps = b.caps;
  const PlannerOptions& o = b.o;
  const MapContext ctx(b.map, o);
  const auto views = generate_task_views(ctx, caps, o);
  int shared = 0, own = 0;
  for (const auto& cl : cluster_views(views, o.eta_r_m)) {
    if (cl.label != kPublic) continue;
    core::PlanRng rng(3);
    const auto tour = mnss_tour(ctx, views, cl.views, {cl.center}, o.eta_r_m, caps.species[0],
                                cl.center + Eigen::Vector3d(-8, 0, 0), std::nullopt, o, rng);
    std::set<uint64_t> wanted, got;
    for (int v : cl.views) wanted.insert(views[size_t(v)].targets.begin(), views[size_t(v)].targets.end());
    for (const auto& v : tour) {
      got.insert(v.targets.begin(), v.targets.end());
      const auto* g = b.map.find(v.ground_key);
      for (uint64_t t : v.targets) {
        const auto* target = b.map.find(t);
        if (!target->facade()) continue;
        const bool its_own = std::any_of(views.begin(), views.end(), [&](const TaskView& w) {
          return w.key == t && w.ground_key == v.ground_key;
        });
        const Eigen::Vector3d sensor = g->center + g->normal.normalized() * o.sensor_height_m;
        const ViewGeometry geo = view_geometry(sensor, g->normal, target->center, target->normal);
        if (its_own) ++own;
        else {
          ++shared;
          EXPECT_TRUE(angles_ok(geo, o, o.shared_view_margin_deg)) << "target " << t;
        }
      }
    }
    EXPECT_EQ(got, wanted) << "cluster " << cl.id;
  }
  EXPECT_GT(shared, 0);
}

// Once a target stayed incomplete when observed from a spot, neither MNSS nor the route's
// pruning hands it to a view standing there again (GiveUpLedger::tried_from).
TEST(Mnss, NoViewStandsWhereItsTargetWasObservedInVain) {
  OneBuilding b;
  const TeamCapabilities& caps = b.caps;
  const PlannerOptions& o = b.o;
  highlevel::HighLevelMap& map = b.map;
  GiveUpLedger ledger{GiveUpRules{.views = 2}};  // two looks: a first look is judged without giving up
  auto tours = [&] {
    const MapContext ctx(map, o, std::nullopt, &ledger);
    const auto views = generate_task_views(ctx, caps, o);
    std::vector<TaskView> route;
    for (const auto& cl : cluster_views(views, o.eta_r_m)) {
      if (cl.label != kPublic) continue;
      core::PlanRng rng(3);
      const auto tour = mnss_tour(ctx, views, cl.views, {cl.center}, o.eta_r_m, caps.species[0],
                                  cl.center + Eigen::Vector3d(-8, 0, 0), std::nullopt, o, rng);
      route.insert(route.end(), tour.begin(), tour.end());
    }
    return prune_route(ctx, route, caps.species[0], o);
  };
  const auto first = tours();
  ASSERT_FALSE(first.empty());
  std::set<uint64_t> tried;
  for (const auto& v : first)
    for (uint64_t t : v.targets)
      if (map.find(t)->facade()) {
        ledger.observed(t, v.position, map.find(t)->voxel_count);
        tried.insert(t);
      }
  ASSERT_FALSE(tried.empty());
  const auto second = tours();
  int handed = 0;
  for (const auto& v : second)
    for (uint64_t t : v.targets) {
      EXPECT_FALSE(ledger.tried_from(t, v.position)) << "target " << t << " again from " << v.position.transpose();
      handed += tried.count(t) ? 1 : 0;
    }
  EXPECT_GT(handed, 0) << "tried targets get views elsewhere";
}

}  // namespace
}  // namespace hexplore::planning
