#include "common/station/experiment_record.h"

namespace hexplore::station {

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

double ExperimentRecord::final_team_completeness() const {
  return completeness.empty() ? 0.0 : completeness.back().team;
}

}  // namespace hexplore::station
