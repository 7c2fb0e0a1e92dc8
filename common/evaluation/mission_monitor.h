#pragma once
// Decides when a mission is over: every live robot's planner reports that no task views
// remain (held for a settling time, so one empty round during map growth does not end it),
// or the time limit is reached. Robots that fall silent are considered gone, so a team that
// loses a member still finishes.

#include <map>
#include <optional>
#include <string>

#include "common/core/liveness.h"

namespace hexplore::evaluation {

struct MissionMonitorOptions {
  double time_limit_s = 1800.0;
  double settle_s = 5.0;        // views must stay at zero this long before the mission ends
  double silent_after_s = 10.0; // a robot with no planning status for this long is gone (core/liveness.h)
  double min_time_s = 5.0;      // never declare completion before this sim time
};

class MissionMonitor {
 public:
  // Throws std::invalid_argument unless silent_after_s is positive.
  explicit MissionMonitor(MissionMonitorOptions options) : options_(options), live_(options.silent_after_s) {}

  // A planning status from `robot`: views it still sees in the (team-shared) map.
  void on_planning_status(const std::string& robot, double sim_time_s, int views_remaining);

  // Called periodically; returns the end reason once the mission is over.
  std::optional<std::string> check(double sim_time_s);

  // Robots heard from within silent_after_s of `sim_time_s`.
  int live_robots(double sim_time_s) const;

 private:
  struct RobotReport {
    double last_time_s = 0.0;
    int views_remaining = -1;
  };

  MissionMonitorOptions options_;
  core::Liveness live_;
  std::map<std::string, RobotReport> reports_;
  std::optional<double> all_empty_since_s_;
};

}  // namespace hexplore::evaluation
