#include <gtest/gtest.h>

#include "common/evaluation/mission_monitor.h"

namespace hexplore::evaluation {
namespace {

MissionMonitorOptions options() {
  MissionMonitorOptions o;
  o.time_limit_s = 100.0;
  o.settle_s = 5.0;
  o.silent_after_s = 10.0;
  o.min_time_s = 2.0;
  return o;
}

TEST(MissionMonitor, EndsWhenEveryLiveRobotSeesNoViewsForTheSettlingTime) {
  MissionMonitor m(options());
  m.on_planning_status("a", 10.0, 0);
  m.on_planning_status("b", 10.0, 3);
  EXPECT_FALSE(m.check(10.0));
  m.on_planning_status("b", 11.0, 0);
  EXPECT_FALSE(m.check(11.0));
  m.on_planning_status("a", 14.0, 0);
  m.on_planning_status("b", 14.0, 0);
  EXPECT_FALSE(m.check(14.0));
  m.on_planning_status("a", 16.0, 0);
  m.on_planning_status("b", 16.0, 0);
  EXPECT_EQ(m.check(16.0), "no task views remain");
}

TEST(MissionMonitor, NewViewsResetTheSettlingClock) {
  MissionMonitor m(options());
  m.on_planning_status("a", 10.0, 0);
  EXPECT_FALSE(m.check(10.0));
  m.on_planning_status("a", 13.0, 4);
  EXPECT_FALSE(m.check(13.0));
  m.on_planning_status("a", 14.0, 0);
  EXPECT_FALSE(m.check(14.0));
  m.on_planning_status("a", 18.0, 0);
  EXPECT_FALSE(m.check(18.0));
  EXPECT_EQ(m.check(19.0), "no task views remain");
}

TEST(MissionMonitor, SilentRobotDoesNotHoldTheMissionOpen) {
  MissionMonitor m(options());
  m.on_planning_status("a", 10.0, 0);
  m.on_planning_status("dead", 10.0, 7);
  std::optional<std::string> end;
  for (double t = 11.0; t <= 30.0 && !end; t += 1.0) {
    m.on_planning_status("a", t, 0);
    end = m.check(t);
  }
  EXPECT_EQ(m.live_robots(30.0), 1);
  EXPECT_EQ(end, "no task views remain");
}

TEST(MissionMonitor, TimeLimitEndsIt) {
  MissionMonitor m(options());
  m.on_planning_status("a", 50.0, 12);
  EXPECT_FALSE(m.check(99.0));
  EXPECT_EQ(m.check(100.0), "time limit");
}

TEST(MissionMonitor, NoReportsNeverCompletes) {
  MissionMonitor m(options());
  EXPECT_FALSE(m.check(50.0));
}

}  // namespace
}  // namespace hexplore::evaluation
