// What the cluster planners (hexplore, its ablations, TSPGA+) make of an assignment: plans with
// costs per robot, agreement with a reference, and the tour that visits a cluster's views in
// graph order (a wall between views must not be crossed back and forth).
#include "common/planning/cluster_tour.h"

#include <gtest/gtest.h>

#include "common/planning/labels.h"

namespace hexplore::planning {
namespace {

// Two rows of ground 2 m apart with a wall between them, joined only at x = 10 (a door).
struct WallScene {
  highlevel::TopologyGraph graph{{1}};
  static uint64_t key(int row, int x) { return uint64_t(100 * row + x + 1); }
  WallScene() {
    for (int row = 0; row < 2; ++row)
      for (int x = 0; x <= 12; ++x) {
        graph.upsert_vertex(key(row, x), {double(x), 2.0 * row, 0.0}, 1);
        if (x > 0) graph.upsert_edge(key(row, x - 1), key(row, x), 1.0);
      }
    graph.upsert_edge(key(0, 10), key(1, 10), 2.0);
  }
  static TaskView view(int row, int x) {
    TaskView v;
    v.key = v.ground_key = key(row, x);
    v.position = {double(x), 2.0 * row, 0.0};
    return v;
  }
};

std::vector<uint64_t> keys(const std::vector<TaskView>& views) {
  std::vector<uint64_t> k;
  for (const auto& v : views) k.push_back(v.key);
  return k;
}

// Two clusters, one robot of species 0 at the depot: cluster 0 holds views on both sides of
// the wall, cluster 1 one view at x = 0 on row 1 (behind the wall from the robot). Travel 1 s between any two nodes; cluster 1
// costs 5 s to execute and is private to species 0.
struct TwoClusters {
  std::vector<TaskView> views = {WallScene::view(1, 3), WallScene::view(0, 2), WallScene::view(1, 7),
                                 WallScene::view(0, 6), WallScene::view(1, 0)};
  std::vector<TaskCluster> clusters;
  AssignmentInstance inst;
  std::vector<RobotState> robots;
  TwoClusters() {
    clusters.push_back({7, kPublic, {0, 1, 2, 3}, {4.5, 1.0, 0.0}, 4});
    clusters.push_back({9, 0, {4}, {0.0, 2.0, 0.0}, 1});
    inst.problem.num_cities = 2;
    inst.problem.robots = {{0}};
    inst.problem.travel = {CostMatrix(3, 1.0)};
    inst.problem.execution = {{0.0, 5.0}};
    inst.city_cluster = {0, 1};
    inst.anchor = {{WallScene::key(0, 2)}, {WallScene::key(1, 0)}};
    inst.speed = {0.5};
    RobotState r;
    r.id = "r0";
    r.species = 0;
    r.position = {0.0, 0.0, 0.0};
    robots.push_back(r);
  }
};

TEST(ClusterTour, PlansCarryClusterOrderLengthAndCosts) {
  const TwoClusters t;
  const std::vector<RobotPlan> plans = cluster_plans(t.inst, t.clusters, t.robots, {{0, 1}});
  ASSERT_EQ(plans.size(), 1u);
  EXPECT_EQ(plans[0].robot_id, "r0");
  EXPECT_EQ(plans[0].cluster_ids, (std::vector<uint64_t>{7, 9}));
  EXPECT_DOUBLE_EQ(plans[0].route_length_m, 2 * 1.0 * 0.5);  // two legs of 1 s at 0.5 m/s
  EXPECT_DOUBLE_EQ(plans[0].cost_s, 1.0 + 1.0 + 5.0);
  EXPECT_DOUBLE_EQ(plans[0].private_cost_s, 1.0 + 5.0);      // only cluster 9 is private
  EXPECT_TRUE(plans[0].route.empty());
}

TEST(ClusterTour, AgreementCountsOnlyClustersTheReferenceAssigns) {
  const TwoClusters t;
  std::vector<RobotPlan> plans = cluster_plans(t.inst, t.clusters, t.robots, {{0, 1}});
  ReferenceSolution ref;
  ref.routes.push_back({"r0", {7}, {}, 0.0});
  EXPECT_EQ(reference_agreement(ref, plans), 1.0);
  ref.routes.push_back({"r1", {9}, {}, 0.0});
  EXPECT_EQ(reference_agreement(ref, plans), 0.5);
  EXPECT_FALSE(reference_agreement(ReferenceSolution{}, plans).has_value());
}

TEST(ClusterTour, AClustersViewsGoInGraphOrderOneSideOfTheWallAtATime) {
  const WallScene scene;
  const TwoClusters t;
  const ClusterViews every = [&](const TaskCluster& cl, const Eigen::Vector3d& start,
                                 const std::optional<Eigen::Vector3d>& end) { return every_view(t.views, cl, start, end); };
  // Euclidean order alone zigzags through the wall.
  EXPECT_EQ(keys(every_view(t.views, t.clusters[0], {0, 0, 0}, std::nullopt)),
            (std::vector<uint64_t>{WallScene::key(0, 2), WallScene::key(1, 3), WallScene::key(0, 6), WallScene::key(1, 7)}));
  // From the robot's vertex at row 0, x = 0, towards cluster 1 behind the wall at x = 0: row 0
  // out to the door, row 1 back (22 m; the zigzag of Euclidean order would cross three times).
  const std::vector<TaskView> tour =
      cluster_tour(scene.graph, t.inst, t.clusters, {0, 1}, t.robots[0], 0, WallScene::key(0, 0), every);
  EXPECT_EQ(keys(tour), (std::vector<uint64_t>{WallScene::key(0, 2), WallScene::key(0, 6), WallScene::key(1, 7),
                                               WallScene::key(1, 3), WallScene::key(1, 0)}));
  // Without a vertex for the robot the views keep the planner's order.
  std::vector<TaskView> planned = every_view(t.views, t.clusters[0], t.robots[0].position, t.clusters[1].center);
  planned.push_back(t.views[4]);
  EXPECT_EQ(keys(cluster_tour(scene.graph, t.inst, t.clusters, {0, 1}, t.robots[0], 0, std::nullopt, every)), keys(planned));
}

}  // namespace
}  // namespace hexplore::planning
