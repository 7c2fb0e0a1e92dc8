#pragma once
// An open travelling-salesman tour on the topology graph: the visiting order of a few stops
// (ground vertices) for one species from a start vertex, by graph travel distance (nearest
// neighbour, then 2-opt and or-opt of 1-3 stops until neither helps). For the baselines that
// order single views (MROMT+'s per-robot tour); distances are asymmetric where body
// clearance costs apply, and the improvement steps account for that.

#include <cstdint>
#include <vector>

#include "common/highlevel/topology_graph.h"

namespace hexplore::planning {

struct GraphTour {
  std::vector<int> order;  // indices into the stops, in visiting order
  double length_m = 0.0;   // graph length from the start through every stop (+inf if one is unreachable)
};

// Stops the species cannot reach from `start` are visited last, in input order.
GraphTour graph_tour(const highlevel::TopologyGraph& graph, uint64_t start, const std::vector<uint64_t>& stops,
                     int species);

}  // namespace hexplore::planning
