// Dead reckoning of team poses: a robot on a straight segment or standing sends one pose per
// heartbeat; drift, a turn or a new motion state make one due at once.
#include <gtest/gtest.h>

#include "common/radio/pose_schedule.h"

namespace hexplore::radio {
namespace {

using V = Eigen::Vector3d;
constexpr int kMoving = 2, kIdle = 1;

TEST(PoseSchedule, StraightDrivingNeedsOnlyTheHeartbeat) {
  PoseSchedule s;
  const V v(0.5, 0.0, 0.0);
  int sent = 0;
  for (int step = 0; step <= 200; ++step) {  // 10 s at 20 Hz
    const double t = step * 0.05;
    const V at = v * t;
    if (s.due(t, at, 0.0, kMoving)) {
      s.sent(t, at, v, 0.0, kMoving);
      ++sent;
    }
  }
  EXPECT_EQ(sent, 6);  // t = 0, 2, 4, 6, 8, 10
}

TEST(PoseSchedule, DriftTurnsAndStateChangesAreSentAtOnce) {
  PoseSchedule s;
  s.sent(0.0, V::Zero(), V(0.5, 0, 0), 0.0, kMoving);
  EXPECT_FALSE(s.due(0.6, V(0.3, 0, 0), 0.0, kMoving));  // as extrapolated
  EXPECT_TRUE(s.due(0.6, V(0.3, 0.35, 0), 0.0, kMoving)); // 0.35 m off the extrapolation
  EXPECT_TRUE(s.due(0.6, V(0.3, 0, 0), 0.5, kMoving));    // turned by 29 degrees
  EXPECT_TRUE(s.due(0.1, V(0.05, 0, 0), 0.0, kIdle));     // went idle: at once, even within min_interval
  EXPECT_FALSE(s.due(0.2, V(0.1, 0.4, 0), 0.0, kMoving)); // drift, but too soon after the last
}

TEST(PoseSchedule, ExtrapolationStopsAtItsHorizon) {
  EXPECT_EQ(extrapolate_pose(V(1, 2, 0), V(0.5, 0, 0), 1.0, 3.0), V(1.5, 2, 0));
  EXPECT_EQ(extrapolate_pose(V(1, 2, 0), V(0.5, 0, 0), 10.0, 3.0), V(2.5, 2, 0));
  EXPECT_EQ(extrapolate_pose(V(1, 2, 0), V(0.5, 0, 0), -1.0, 3.0), V(1, 2, 0));
  EXPECT_THROW(PoseSchedule(PoseScheduleOptions{.heartbeat_s = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::radio
