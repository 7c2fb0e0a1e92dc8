#pragma once
// Cost model of the assignment (paper eq. 4-xx-delta and 4-xx-w) on the topology graph:
// execution time delta(tau, k) and transition time w(tau_i, tau_j, k), +inf where the
// cluster's label excludes species k or the graph does not connect. Builds the HMDMTSP
// instance over the clusters that at least one robot can serve.

#include <cstdint>
#include <optional>
#include <vector>

#include "common/planning/capabilities.h"
#include "common/planning/cluster_work.h"
#include "common/planning/clustering.h"
#include "common/planning/mtsp/mtsp_problem.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

struct AssignmentInstance {
  MtspProblem problem;                 // cities = kept clusters, robots = the team
  std::vector<int> city_cluster;       // city -> index into the cluster list
  std::vector<int> dropped;            // cluster indices nobody can serve
  std::vector<uint64_t> robot_vertex;  // depot vertex per robot (0 when none)
  // anchor[cluster][species]: p'(tau), the nearest vertex the species may stand on.
  std::vector<std::vector<uint64_t>> anchor;
  // Graph length in metres between robot depots / cluster anchors, per species (travel * speed).
  std::vector<double> speed;           // per species
};

// The map a cluster's cover is computed on (cluster_work.h, the cover reading of delta).
struct CoverReading {
  const MapContext& context;
  const PlannerOptions& options;
};

// `robot_vertices` is RoundInputs::robot_vertices (index = robot). `cover` null: delta walks to
// and dwells at every task view (the paper's formula as written); otherwise it charges the
// cover of the cluster's targets. Either way a species must reach every view of a cluster.
AssignmentInstance build_assignment(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                                    const std::vector<TaskCluster>& clusters, const TeamCapabilities& team,
                                    const std::vector<RobotState>& robots,
                                    const std::vector<std::optional<uint64_t>>& robot_vertices,
                                    const CoverReading* cover = nullptr);

}  // namespace hexplore::planning
