// The plan messages carry what a teammate needs of a planning round: a shared team solution
// comes back as the same reference routes, and a path keeps its waypoints, goal and speed.

#include <gtest/gtest.h>

#include "common/planning/plan_proto.h"

namespace hexplore::planning {
namespace {

PlanResult two_robot_solution() {
  PlanResult r;
  r.round = 42;
  r.planner = "hexplore";
  r.fitness = 123.5;
  RobotPlan a;
  a.robot_id = "slugcat1";
  a.cluster_ids = {7, 3};
  a.cluster_centers = {{1.0, 2.0, 0.0}, {-4.5, 8.25, 1.5}};
  a.route_length_m = 17.5;
  RobotPlan b;
  b.robot_id = "mr1000a";
  b.route_length_m = 0.0;  // nothing assigned: still one (empty) sequence
  r.robots = {a, b};
  return r;
}

TEST(PlanProto, ASharedSolutionComesBackAsTheSameReferenceRoutes) {
  const v1::TeamSolution wire = to_proto(two_robot_solution());
  EXPECT_EQ(wire.round(), 42u);
  EXPECT_EQ(wire.planner(), "hexplore");

  const ReferenceSolution ref = reference_from_proto(wire, "slugcat1");
  EXPECT_EQ(ref.source_robot, "slugcat1");
  EXPECT_EQ(ref.round, 42u);
  ASSERT_EQ(ref.routes.size(), 2u);
  EXPECT_EQ(ref.routes[0].robot_id, "slugcat1");
  EXPECT_EQ(ref.routes[0].cluster_ids, (std::vector<uint64_t>{7, 3}));
  ASSERT_EQ(ref.routes[0].centers.size(), 2u);
  EXPECT_EQ(ref.routes[0].centers[1], Eigen::Vector3d(-4.5, 8.25, 1.5));
  EXPECT_DOUBLE_EQ(ref.routes[0].length_m, 17.5);
  EXPECT_EQ(ref.routes[1].robot_id, "mr1000a");
  EXPECT_TRUE(ref.routes[1].cluster_ids.empty());
  EXPECT_EQ(ref.route_of("mr1000a"), &ref.routes[1]);
}

TEST(PlanProto, APathKeepsItsWaypointsGoalAndSpeed) {
  ExecutablePlan path;
  path.valid = true;
  path.waypoints = {{0.0, 0.0, 0.0}, {1.5, -2.0, 0.25}};
  path.goal.position = {1.5, -2.0, 0.25};
  path.goal.look_at = {3.0, -2.0, 4.0};
  path.goal.ground_key = 99;
  path.goal.targets = {5, 6};

  const v1::ExecutablePath wire = path_to_proto(9, path, 0.4);
  EXPECT_EQ(wire.round(), 9u);
  EXPECT_DOUBLE_EQ(wire.speed_mps(), 0.4);
  ASSERT_EQ(wire.waypoints_m_size(), 2);
  EXPECT_DOUBLE_EQ(wire.waypoints_m(1).y(), -2.0);
  EXPECT_DOUBLE_EQ(wire.waypoints_m(1).z(), 0.25);
  EXPECT_EQ(wire.goal().ground_supervoxel(), 99u);
  EXPECT_DOUBLE_EQ(wire.goal().look_at_m().z(), 4.0);
  ASSERT_EQ(wire.goal().target_supervoxels_size(), 2);
  EXPECT_EQ(wire.goal().target_supervoxels(1), 6u);
}

}  // namespace
}  // namespace hexplore::planning
