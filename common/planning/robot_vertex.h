#pragma once
// Where a robot joins the topology graph. The Euclidean-nearest passable vertex can be a
// stray one (a rubble top, a patch beside a wall) cut off from the ground the robot drives
// on, which would make every cluster look unreachable to it; so the vertex is chosen among
// those around the robot as the one in the largest reachable component.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "common/highlevel/topology_graph.h"

namespace hexplore::planning {

// The graph vertex a robot of `species` at `p` starts from; nullopt for an empty graph.
std::optional<uint64_t> robot_vertex(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& p, int species);

}  // namespace hexplore::planning
