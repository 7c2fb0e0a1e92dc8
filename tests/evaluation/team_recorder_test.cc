#include <gtest/gtest.h>

#include <cmath>

#include "common/core/team_config.h"
#include "common/evaluation/team_recorder.h"
#include "tests/evaluation/status_fixture.h"

namespace hexplore::evaluation {
namespace {

core::TeamConfig team() {
  return core::parse_team_config(
      "species: [{builtin: SLUGCAT}, {builtin: MR1000}]\n"
      "robots: [{id: a, species: SLUGCAT}, {id: b, species: MR1000}]\n",
      "test");
}

v1::RobotPose pose_at(double x, double y, double odometry) {
  v1::RobotPose p;
  p.mutable_pose()->mutable_position_m()->set_x(x);
  p.mutable_pose()->mutable_position_m()->set_y(y);
  p.set_odometry_m(odometry);
  return p;
}

v1::ServiceStatus planning_status(double round, double time_s, double views) {
  v1::ServiceStatus s;
  s.set_service("planning");
  auto add = [&](std::string_view name, double value) {
    auto* v = s.add_values();
    v->set_name(std::string(name));
    v->set_value(value);
  };
  add(kPlanningRound, round);
  add(kPlanningTime, time_s);
  add(kViewsRemaining, views);
  return s;
}

TEST(TeamRecorder, CategoriesFollowThePaper) {
  EXPECT_EQ(communication_category("team/pose"), "pose");
  EXPECT_EQ(communication_category("team/map"), "incremental_map");
  EXPECT_EQ(communication_category("team/path"), "executable_path");
  EXPECT_EQ(communication_category("team/plan"), "exploration_route");
  EXPECT_FALSE(communication_category("team/mission"));
  EXPECT_FALSE(communication_category("robot/a/scan"));
}

TEST(TeamRecorder, IgnoresEverythingBeforeStart) {
  const auto t = team();
  TeamRecorder r(t);
  r.on_pose("a", 1.0, pose_at(0, 0, 0));
  r.on_team_message("a", "team/pose", 100);
  EXPECT_TRUE(r.record().robots.at("a").positions_m.empty());
  EXPECT_TRUE(r.record().team_bytes.empty());
}

using testing::status;

TEST(TeamRecorder, TrajectoryLengthUsesOdometryAndBytesAreCategorised) {
  const auto t = team();
  TeamRecorder r(t);
  r.on_status("a", "sim", status({{"odometry_m", 5.0}, {"collisions", 1}}));  // before the start
  r.start(10.0);
  for (int i = 0; i <= 10; ++i) {
    r.on_pose("a", 10.0 + i, pose_at(i * 1.0, 0.0, 0.0));
    r.on_pose("b", 10.0 + i, pose_at(0.0, i * 2.0, 0.0));
  }
  EXPECT_NEAR(r.record().robots.at("b").length_m, 20.0, 1e-9);  // a driver without odometry: chords
  // The sim's odometry (which follows every bend the sparse radio poses cut) since the start.
  r.on_status("a", "sim", status({{"odometry_m", 17.5}, {"collisions", 2}}));
  EXPECT_NEAR(r.record().robots.at("a").length_m, 12.5, 1e-9);
  EXPECT_EQ(r.record().robots.at("a").collisions, 2u);
  EXPECT_EQ(r.record().robots.at("a").positions_m.size(), 11u);
  EXPECT_NEAR(r.mission_time_s(), 10.0, 1e-9);
  r.on_team_message("a", "team/map", 300);
  r.on_team_message("a", "team/map", 200);
  r.on_team_message("b", "team/plan", 50);
  r.on_team_message("zz", "team/plan", 50);  // unknown robot: not counted
  EXPECT_EQ(r.record().team_bytes.at("a").at("incremental_map"), 500u);
  EXPECT_EQ(r.record().team_bytes.at("b").at("exploration_route"), 50u);
  EXPECT_FALSE(r.record().team_bytes.contains("zz"));
  EXPECT_FALSE(r.on_pose("zz", 11.0, pose_at(0, 0, 0)));
  EXPECT_EQ(r.record().team_messages.at("a").at("incremental_map"), 2u);
}

TEST(TeamRecorder, OrientationsFollowThePositions) {
  const auto t = team();
  TeamRecorder r(t);
  r.start(0.0);
  v1::RobotPose turned = pose_at(1.0, 0.0, 0.0);
  auto* q = turned.mutable_pose()->mutable_orientation();
  q->set_w(2.0), q->set_z(2.0);  // 90 deg about z, not normalised on the wire
  r.on_pose("a", 0.0, pose_at(0.0, 0.0, 0.0));  // no orientation on the wire: identity
  r.on_pose("a", 1.0, turned);
  const RobotTrack& a = r.record().robots.at("a");
  ASSERT_EQ(a.orientations.size(), a.positions_m.size());
  EXPECT_TRUE(a.orientations[0].isApprox(Eigen::Quaterniond::Identity()));
  EXPECT_NEAR(a.orientations[1].w(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(a.orientations[1].z(), std::sqrt(0.5), 1e-12);
}

TEST(TeamRecorder, StatusCountersCountFromTheStart) {
  const auto t = team();
  TeamRecorder r(t);
  r.on_status("b", "hlmap", status({{"gaps_detected", 2}, {"full_map_bytes", 1000}, {"supervoxels", 50}}));
  r.start(0.0);
  r.on_status("b", "hlmap", status({{"gaps_detected", 5}, {"full_map_bytes", 4000}, {"radio_lost", 7}}));
  r.on_status("b", "mapping", status({{"raw_map_bytes", 90000}, {"radio_lost", 1}}));
  const auto& track = r.record().robots.at("b");
  EXPECT_DOUBLE_EQ(track.counter("hlmap.gaps_detected"), 3.0);
  EXPECT_DOUBLE_EQ(track.counter("hlmap.full_map_bytes"), 3000.0);
  EXPECT_DOUBLE_EQ(track.counter("mapping.raw_map_bytes"), 90000.0);  // first heard after the start: all of it
  EXPECT_DOUBLE_EQ(track.counter_sum("radio_lost"), 8.0);  // every service's, summed
  EXPECT_FALSE(track.counters.contains("hlmap.supervoxels"));  // not a counter the record keeps
}

TEST(TeamRecorder, MapConvergenceIsTheLatestSequencesHeard) {
  const auto t = team();
  TeamRecorder r(t);
  const auto& record = r.record();
  EXPECT_EQ(record.increments_behind("a", "b"), -1.0);  // nothing heard yet
  r.on_status("a", "hlmap", status({{"own_increment_seq", 40}, {"synced_seq.b", 12}, {"synced_seq.ghost", 3}}));
  r.on_status("b", "hlmap", status({{"own_increment_seq", 30}, {"synced_seq.a", 40}}));
  EXPECT_EQ(record.increments_behind("a", "b"), 18.0);  // b is at 30, a applied 12 of them
  EXPECT_EQ(record.increments_behind("b", "a"), 0.0);
  EXPECT_FALSE(record.robots.at("a").synced_seq.contains("ghost"));  // not a robot of the team
  // A partition heals: a catches up with b, whose sequence went on.
  r.on_status("b", "hlmap", status({{"own_increment_seq", 55}, {"synced_seq.a", 41}}));
  r.on_status("a", "hlmap", status({{"own_increment_seq", 42}, {"synced_seq.b", 54}}));
  EXPECT_EQ(record.increments_behind("a", "b"), 1.0);  // one in flight
  EXPECT_EQ(record.increments_behind("b", "a"), 1.0);
  EXPECT_EQ(record.increments_behind("a", "nobody"), -1.0);
  // Not kept as counters.
  EXPECT_FALSE(record.robots.at("a").counters.contains("hlmap.own_increment_seq"));
}

TEST(TeamRecorder, OutOfSyncStretchesFollowTheHlmapsStatus) {
  const auto t = team();
  TeamRecorder r(t);
  r.on_status("a", "hlmap", status({{"in_sync.b", 0}}));  // before the start: not recorded
  r.start(0.0);
  const double in_sync[] = {1, 1, 0, 0, 0, 1, 1, 0};  // one status per second
  for (int i = 0; i < 8; ++i) {
    r.on_pose("a", i, pose_at(0, 0, 0));
    r.on_status("a", "hlmap", status({{"in_sync.b", in_sync[i]}, {"in_sync.ghost", 0}}));
  }
  const auto& unsynced = r.record().robots.at("a").unsynced;
  ASSERT_EQ(unsynced.size(), 1u);  // not the ghost: not a robot of the team
  const std::vector<std::pair<double, double>> want = {{2.0, 5.0}, {7.0, -1.0}};
  EXPECT_EQ(unsynced.at("b"), want);
}

TEST(TeamRecorder, LongestBlockedStretchPerRobot) {
  // Blocked 2 s, moving, blocked 5 s (to the end): 5 s; a robot never blocked: 0.
  const auto t = team();
  TeamRecorder r(t);
  auto in_state = [](v1::MotionState s) {
    v1::RobotPose p = pose_at(0, 0, 0);
    p.set_state(s);
    return p;
  };
  r.on_pose("a", 0.5, in_state(v1::MOTION_STATE_BLOCKED));  // before start: not counted
  r.start(1.0);
  const char* states = "MMBBBMMBBBBBB";  // one pose per second from t = 1 s
  for (int i = 0; states[i]; ++i) {
    r.on_pose("a", 1.0 + i, in_state(states[i] == 'B' ? v1::MOTION_STATE_BLOCKED : v1::MOTION_STATE_MOVING));
    r.on_pose("b", 1.0 + i, in_state(v1::MOTION_STATE_STOPPED));
  }
  EXPECT_DOUBLE_EQ(r.record().robots.at("a").longest_blocked_s, 5.0);
  EXPECT_DOUBLE_EQ(r.record().robots.at("b").longest_blocked_s, 0.0);
}

TEST(TeamRecorder, PlanningTimeRecordedOncePerRound) {
  const auto t = team();
  TeamRecorder r(t);
  r.start(0.0);
  EXPECT_EQ(r.on_planning_status("a", planning_status(1, 0.05, 12)), 12);
  r.on_planning_status("a", planning_status(1, 0.05, 12));  // same round repeated in the next status
  r.on_planning_status("a", planning_status(2, 0.07, 3));
  ASSERT_EQ(r.record().planning_times_s.at("a").size(), 2u);
  EXPECT_DOUBLE_EQ(r.record().planning_times_s.at("a")[1], 0.07);
  v1::ServiceStatus empty;
  EXPECT_EQ(r.on_planning_status("b", empty), -1);
}

}  // namespace
}  // namespace hexplore::evaluation
