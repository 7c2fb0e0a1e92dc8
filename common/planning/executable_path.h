#pragma once
// The executable path to a task view (paper: "executable paths ... using motion planning"):
// the topology-graph route for the robot's species from where it stands to the view's ground
// vertex, through each vertex's clearance waypoint. The route follower (route_follower.h) is
// its one user during a mission.

#include <unordered_set>

#include <Eigen/Core>

#include "common/highlevel/topology_graph.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

// The executable path from `from` to the goal view along the topology graph for a species,
// through each vertex's clearance waypoint (TopologyGraph::waypoint) and preferring vertices
// with room for the body (clearance costs, when the graph has body radii).
// `avoid` (optional): vertices the robot found it cannot pass (blocked there); the path goes
// around them, or is invalid when it cannot.
ExecutablePlan executable_path(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& from, int species,
                               const TaskView& goal, const std::unordered_set<uint64_t>* avoid = nullptr);

}  // namespace hexplore::planning
