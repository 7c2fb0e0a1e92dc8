#include "common/station/experiment_record.h"

namespace hexplore::station {

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
