#include "common/evaluation/mission_monitor.h"

namespace hexplore::evaluation {

void MissionMonitor::on_planning_status(const std::string& robot, double sim_time_s, int views_remaining) {
  auto& report = reports_[robot];
  report.last_time_s = sim_time_s;
  report.views_remaining = views_remaining;
}

int MissionMonitor::live_robots(double sim_time_s) const {
  int live = 0;
  for (const auto& [_, report] : reports_)
    if (live_.fresh(sim_time_s - report.last_time_s)) ++live;
  return live;
}

std::optional<std::string> MissionMonitor::check(double sim_time_s) {
  if (sim_time_s >= options_.time_limit_s) return "time limit";
  bool any_live = false;
  bool all_empty = true;
  for (const auto& [_, report] : reports_) {
    if (!live_.fresh(sim_time_s - report.last_time_s)) continue;
    any_live = true;
    if (report.views_remaining != 0) all_empty = false;
  }
  if (!any_live || !all_empty || sim_time_s < options_.min_time_s) {
    all_empty_since_s_.reset();
    return std::nullopt;
  }
  if (!all_empty_since_s_) all_empty_since_s_ = sim_time_s;
  if (sim_time_s - *all_empty_since_s_ >= options_.settle_s) return "no task views remain";
  return std::nullopt;
}

}  // namespace hexplore::evaluation
