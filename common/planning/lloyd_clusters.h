#pragma once
// MROMT+'s capability-aware Lloyd clustering (BASELINES.md; after CoScan's modified Lloyd
// algorithm for the optimal mass-transport assignment): clusters start one per robot at
// its position; each view joins the cluster it is the fewest seconds of travel from among the
// clusters whose species may take it; each centre moves to the mean of its views, snapped to
// a vertex its species reaches; a cluster wider than the compactness distance splits (a new
// centre at its farthest view), two of one species that fit within it together merge; at
// most max_iterations rounds, fewer once nothing changes.

#include <cstdint>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/topology_graph.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct LloydCluster {
  int species = 0;
  uint64_t centre_vertex = 0;                        // a ground vertex the species reaches
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // its position
  std::vector<int> members;                          // indices into the views, ascending
};

struct LloydSeed {
  int species = 0;
  uint64_t vertex = 0;
};

struct LloydOptions {
  double compactness_m = 5.0;  // split / merge distance (eta_r)
  int max_iterations = 10;
};

// `species_mask[v]`: bit k when species k may take view v; `reachable[k]`: the ground species
// k reaches (RoundInputs::reachable); `speed[k]` in m/s. Views no cluster's species may take
// (or reach from its centre) stay out of every cluster. Non-empty clusters only, in creation
// order; deterministic for the same inputs.
std::vector<LloydCluster> capability_lloyd(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                                           const std::vector<int>& species_mask, const std::vector<LloydSeed>& seeds,
                                           const std::vector<std::unordered_set<uint64_t>>& reachable,
                                           const std::vector<double>& speed, const LloydOptions& options);

}  // namespace hexplore::planning
