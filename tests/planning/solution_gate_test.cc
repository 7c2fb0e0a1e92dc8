#include "services/planning/solution_gate.h"

#include <gtest/gtest.h>

namespace hexplore::planning_service {
namespace {

v1::TeamSolution solution(const std::string& planner, std::vector<uint64_t> first, double length_m = 10.0) {
  v1::TeamSolution s;
  s.set_planner(planner);
  auto* seq = s.add_sequences();
  seq->set_robot_id("r1");
  for (uint64_t id : first) seq->add_cluster_ids(id);
  seq->set_route_length_m(length_m);
  s.add_sequences()->set_robot_id("r2");
  return s;
}

TEST(SolutionGate, TheSameSolutionWaitsForTheRefreshTime) {
  SolutionGate gate(10.0);
  EXPECT_TRUE(gate.should_send(solution("hexplore", {1, 2}), false, 0.0));  // the first one goes
  EXPECT_FALSE(gate.should_send(solution("hexplore", {1, 2}), false, 1.0));
  // Lengths change as robots move; the assignment is the same.
  EXPECT_FALSE(gate.should_send(solution("hexplore", {1, 2}, 7.5), false, 2.0));
  EXPECT_TRUE(gate.should_send(solution("hexplore", {1, 2}), false, 10.0));  // refresh
  EXPECT_FALSE(gate.should_send(solution("hexplore", {1, 2}), false, 11.0));
}

TEST(SolutionGate, ANewAssignmentPlannerOrGivenUpChangeGoesAtOnce) {
  SolutionGate gate(10.0);
  ASSERT_TRUE(gate.should_send(solution("hexplore", {1, 2}), false, 0.0));
  EXPECT_TRUE(gate.should_send(solution("hexplore", {2, 1}), false, 1.0));   // order
  EXPECT_TRUE(gate.should_send(solution("hexplore", {2}), false, 2.0));      // a cluster done
  EXPECT_TRUE(gate.should_send(solution("no-mnss", {2}), false, 3.0));       // planner switched
  EXPECT_TRUE(gate.should_send(solution("no-mnss", {2}), true, 4.0));        // given-up news
  v1::TeamSolution moved = solution("no-mnss", {});
  moved.mutable_sequences(1)->add_cluster_ids(2);                          // to the other robot
  EXPECT_TRUE(gate.should_send(moved, false, 5.0));
  EXPECT_FALSE(gate.should_send(moved, false, 6.0));
}

// A robot whose solution no teammate would choose sends it without sequences (RouteSharing::
// kReferenceOnly): what the teammates hold is still the last sequences sent.
TEST(SolutionGate, WithoutSequencesOnlyThePlannerNewsAndRefreshCount) {
  SolutionGate gate(10.0);
  ASSERT_TRUE(gate.should_send(solution("hexplore", {1, 2}), false, 0.0));
  v1::TeamSolution bare;
  bare.set_planner("hexplore");
  EXPECT_FALSE(gate.should_send(bare, false, 1.0));
  EXPECT_TRUE(gate.should_send(bare, true, 2.0));  // given-up news
  EXPECT_FALSE(gate.should_send(bare, false, 3.0));
  // The sequences the teammates hold are still {1, 2}: the same again waits, new ones go.
  EXPECT_FALSE(gate.should_send(solution("hexplore", {1, 2}), false, 4.0));
  EXPECT_TRUE(gate.should_send(solution("hexplore", {2}), false, 5.0));
  bare.set_planner("no-mnss");
  EXPECT_TRUE(gate.should_send(bare, false, 6.0));  // planner switched
  EXPECT_TRUE(gate.should_send(bare, false, 16.0));  // refresh
}

}  // namespace
}  // namespace hexplore::planning_service
