#include "common/evaluation/experiment_record.h"

#include <algorithm>
#include <map>

namespace hexplore::evaluation {

double RobotTrack::counter(const std::string& key) const {
  auto it = counters.find(key);
  return it == counters.end() ? 0.0 : it->second;
}

double RobotTrack::counter_sum(const std::string& value) const {
  double sum = 0.0;
  const std::string suffix = "." + value;
  for (const auto& [key, v] : counters)
    if (key.size() > suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0) sum += v;
  return sum;
}

double ExperimentRecord::accumulated_completeness() const {
  if (completeness.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& [robot, value] : completeness.back().per_robot) sum += value;
  return sum;
}

double ExperimentRecord::increments_behind(const std::string& robot, const std::string& source) const {
  const auto r = robots.find(robot), s = robots.find(source);
  if (r == robots.end() || s == robots.end() || s->second.own_increment_seq < 0) return -1.0;
  const auto synced = r->second.synced_seq.find(source);
  if (synced == r->second.synced_seq.end()) return -1.0;
  return std::max(0.0, s->second.own_increment_seq - synced->second);
}

double ExperimentRecord::final_team_completeness() const {
  return completeness.empty() ? 0.0 : completeness.back().team;
}

std::vector<OpenTargetRow> ExperimentRecord::latest_open_targets() const {
  std::map<std::string, double> last;
  for (const auto& t : open_targets) last[t.robot] = std::max(last[t.robot], t.sim_time_s);
  std::vector<OpenTargetRow> out;
  for (const auto& t : open_targets)
    if (t.sim_time_s == last[t.robot]) out.push_back(t);
  return out;
}

void ExperimentRecord::add_open_targets_report(const std::string& robot, double sim_time_s,
                                               std::vector<OpenTargetRow> rows) {
  std::erase_if(open_targets, [&](const OpenTargetRow& t) { return t.robot == robot && t.sim_time_s == sim_time_s; });
  for (auto& row : rows) {
    row.robot = robot;
    row.sim_time_s = sim_time_s;
    open_targets.push_back(std::move(row));
  }
}

}  // namespace hexplore::evaluation
