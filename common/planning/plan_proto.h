#pragma once
// Conversions between planning results and the v1 plan messages (team/plan, route, path).

#include <string>

#include "common/planning/planning_types.h"
#include "hexplore/v1/plan.pb.h"

namespace hexplore::planning {

v1::TeamSolution to_proto(const PlanResult& result);
// A teammate's shared solution as a reference candidate; `source_robot` is the sender.
ReferenceSolution reference_from_proto(const v1::TeamSolution& solution, const std::string& source_robot);
v1::TaskView to_proto(const TaskView& view);
v1::ExplorationRoute route_to_proto(uint64_t round, const std::vector<TaskView>& views);
v1::ExecutablePath path_to_proto(uint64_t round, const ExecutablePlan& path, double speed_mps);

}  // namespace hexplore::planning
