#pragma once
// An open travelling-salesman tour on the topology graph: the visiting order of a few stops
// (ground vertices) for one species from a start vertex, optionally towards an end vertex, by
// graph travel distance (nearest neighbour, then 2-opt and or-opt of 1-3 stops until neither
// helps). MROMT+ orders each robot's views with it; hexplore orders the views of each assigned
// cluster with it (paper eq. 4-xx-delta: a cluster's cost is graph distance, and walls make
// Euclidean order cross them back and forth). Distances are asymmetric where body clearance
// costs apply, and the improvement steps account for that.

#include <cstdint>
#include <optional>
#include <vector>

#include "common/highlevel/topology_graph.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct GraphTour {
  std::vector<int> order;  // indices into the stops, in visiting order
  // Graph length from the start through every stop (and on to `end` when given and reachable
  // from the start); +inf if a stop is unreachable.
  double length_m = 0.0;
};

// Stops the species cannot reach from `start` are visited last, in input order. With `end`,
// the path's last leg (last stop -> end) counts in the length the improvement steps minimise.
GraphTour graph_tour(const highlevel::TopologyGraph& graph, uint64_t start, const std::vector<uint64_t>& stops,
                     int species, std::optional<uint64_t> end = std::nullopt);

// `views` in graph_tour order over their ground vertices, from `start` towards `end`.
std::vector<TaskView> order_views_on_graph(const highlevel::TopologyGraph& graph, uint64_t start,
                                           const std::vector<TaskView>& views, int species,
                                           std::optional<uint64_t> end = std::nullopt);

}  // namespace hexplore::planning
