// The station's mission commands as one robot reads them: only its own or the team's, an
// emergency stop lifted only by a start, a planner switch no change of state.
#include "common/service/mission_state.h"

#include <gtest/gtest.h>

namespace hexplore::service {
namespace {

v1::MissionCommand stop(const std::string& target = "") {
  v1::MissionCommand c;
  c.set_target_robot(target);
  c.mutable_stop();
  return c;
}
v1::MissionCommand start() {
  v1::MissionCommand c;
  c.mutable_start();
  return c;
}
v1::MissionCommand estop(const std::string& why) {
  v1::MissionCommand c;
  c.mutable_emergency_stop()->set_reason(why);
  return c;
}

TEST(MissionState, FollowsCommandsForThisRobotOrTheTeam) {
  MissionState m;
  EXPECT_TRUE(m.active());
  EXPECT_FALSE(m.apply(stop("r2"), "r1").has_value());  // a teammate's
  EXPECT_TRUE(m.active());
  EXPECT_EQ(m.apply(stop("r1"), "r1"), MissionState::State::kStopped);
  EXPECT_EQ(m.reason(), "mission stopped");
  EXPECT_EQ(m.apply(start(), "r1"), MissionState::State::kActive);
  EXPECT_TRUE(m.reason().empty());
  v1::MissionCommand sw;
  sw.mutable_switch_planner()->set_planner("no-mnss");
  EXPECT_FALSE(m.apply(sw, "r1").has_value());
  EXPECT_TRUE(addressed_to(sw, "r1"));
  EXPECT_FALSE(addressed_to(stop("r2"), "r1"));
}

TEST(MissionState, OnlyAStartLiftsAnEmergencyStop) {
  MissionState m;
  EXPECT_EQ(m.apply(estop("operator"), "r1"), MissionState::State::kEmergency);
  EXPECT_EQ(m.reason(), "emergency stop: operator");
  EXPECT_EQ(m.apply(stop(), "r1"), MissionState::State::kEmergency);
  EXPECT_EQ(m.apply(start(), "r1"), MissionState::State::kActive);
}

TEST(MissionState, CanWaitForTheStart) {
  MissionState m(/*waiting_for_start=*/true);
  EXPECT_FALSE(m.active());
  EXPECT_EQ(m.reason(), "waiting for mission start");
  m.apply(start(), "r1");
  EXPECT_TRUE(m.active());
}

}  // namespace
}  // namespace hexplore::service
