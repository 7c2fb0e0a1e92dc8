#include "common/safety/decision_trace.h"

#include <gtest/gtest.h>

namespace hexplore::safety {
namespace {

Fragment teammate_at(const std::string& id, const Eigen::Vector3d& p) {
  Fragment f;
  f.robot_id = id;
  f.position_m = p;
  return f;
}

Decision follow(const std::string& reason) {
  Decision d;
  d.kind = DecisionKind::kFollow;
  d.reason = reason;
  d.waypoints = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)};
  return d;
}

TEST(DecisionTrace, AnUnchangedDecisionFarFromTeammatesIsLeftOut) {
  const std::vector<Fragment> far = {teammate_at("b", {10, 0, 0})};
  EXPECT_FALSE(worth_tracing(follow(""), follow(""), Eigen::Vector3d::Zero(), far));
  EXPECT_TRUE(worth_tracing(follow("yield to b (crossing)"), follow(""), Eigen::Vector3d::Zero(), far));
}

TEST(DecisionTrace, EveryDecisionNearATeammateIsKept) {
  std::vector<Fragment> near = {teammate_at("b", {10, 0, 0})};
  near[0].trail_m = {Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(10, 0, 0)};  // may still be at x = 2
  EXPECT_TRUE(worth_tracing(follow(""), follow(""), Eigen::Vector3d::Zero(), near));
}

TEST(DecisionTrace, TheLineNamesTheDecisionAndTheNearTeammatesOnly) {
  const std::vector<Fragment> peers = {teammate_at("near", {1, 0, 0}), teammate_at("far", {20, 0, 0})};
  const std::string line = decision_trace_json(12.5, Eigen::Vector3d::Zero(), follow("too close to \"near\""), peers);
  EXPECT_EQ(line.back(), '\n');
  EXPECT_NE(line.find("\"t\": 12.50"), std::string::npos);
  EXPECT_NE(line.find("\"kind\": \"follow\""), std::string::npos);
  EXPECT_NE(line.find("too close to \\\"near\\\""), std::string::npos);  // quotes escaped
  EXPECT_NE(line.find("\"path\": [[0.00, 0.00], [1.00, 0.00]]"), std::string::npos);
  EXPECT_NE(line.find("\"id\": \"near\""), std::string::npos);
  EXPECT_EQ(line.find("\"far\""), std::string::npos);
}

}  // namespace
}  // namespace hexplore::safety
