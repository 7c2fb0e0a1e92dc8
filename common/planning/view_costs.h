#pragma once
// The cost model of the baselines that assign single task views (MDVRP+, MROMT+), the view
// counterpart of cost_model.h: travel time = the species' topology-graph distance / its
// speed, observation time = 1 / observation speed for a facade view (0 for ground), and
// +inf where the view's requirements exceed the robot's capability (matches(), not the
// label: a capable robot may take a view labelled for a weaker species) or the robot cannot
// drive there (not on the ground its species reaches, or not connected to the robot).

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <vector>

#include "common/highlevel/topology_graph.h"
#include "common/planning/capabilities.h"
#include "common/planning/mtsp/mtsp_problem.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

// Whether a robot of `species` may take `view` at all: requirements met and the view's ground
// on `reachable` (the species' RoundInputs::reachable set).
bool species_can_take(const TaskView& view, const SpeciesCapability& species,
                      const std::unordered_set<uint64_t>& reachable);

// Observation time of a view for a species, in seconds.
double observation_time_s(const TaskView& view, const SpeciesCapability& species);

struct ViewCosts {
  // Nodes 0..N-1 are the views some robot can serve, in the input (key) order; node N + r is
  // robot r's depot (its start vertex).
  std::vector<int> view_of_node;
  std::vector<int> unservable;            // view indices nobody can serve
  std::vector<int> node_species_mask;     // bit k: species k may take the node (requirements, ground)
  std::vector<int> robot_species;
  std::vector<std::optional<uint64_t>> robot_vertex;
  std::vector<double> speed;              // per species, m/s
  // travel[k](a, b): seconds from node a to node b for species k; +inf where k cannot take b
  // (or a), from a depot of another species, or into a depot (routes are open).
  std::vector<CostMatrix> travel;
  std::vector<std::vector<double>> service;  // [k][node]: observation time, +inf where k cannot take it
  // eligible[r][node]: robot r may serve the node (species may take it and r is connected to it).
  std::vector<std::vector<char>> eligible;

  int nodes() const { return int(view_of_node.size()); }
  int depot(int robot) const { return nodes() + robot; }
};

// `robot_vertices` and `reachable` are RoundInputs' (index = robot, and = species). Only species that some robot has
// get a matrix (the others stay empty and every entry reads +inf through service).
ViewCosts build_view_costs(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                           const TeamCapabilities& team, const std::vector<RobotState>& robots,
                           const std::vector<std::optional<uint64_t>>& robot_vertices,
                           const std::vector<std::unordered_set<uint64_t>>& reachable);

}  // namespace hexplore::planning
