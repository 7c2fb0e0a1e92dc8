#pragma once
// What every planner shares in a round (BASELINES.md "same machinery"): the request checked
// against the team, the ground each species can drive to, the map context (occlusion grid,
// ground index, given-up targets) and the task views with their requirements and labels.
// Planners differ only in what they do with these.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "common/planning/capabilities.h"
#include "common/planning/planning_types.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct RoundInputs {
  // Where each robot joins the topology graph (index = robot; robot_vertex() on the graph
  // species of its species), nullopt off an empty graph. Computed once per round: every
  // later stage (costs, Voronoi partition, priority batch) starts from these.
  std::vector<std::optional<uint64_t>> robot_vertices;
  // Ground vertices each species can drive to from where its robots stand (index = species),
  // inside the stand region and with room for the species' body.
  std::vector<std::unordered_set<uint64_t>> reachable;
  std::unique_ptr<MapContext> context;  // views stand only on ground some robot reaches
  std::vector<TaskView> views;          // ascending key order
  ViewGenerationStats stats;
  std::vector<TargetRecord> targets;    // what became of each ISE supervoxel (when asked for)
};

// Throws std::invalid_argument (naming `planner`) when the request has no map, its self
// index is outside the team, or a robot's species is not one of `team`'s.
void check_request(const std::string& planner, const PlanRequest& request, const TeamCapabilities& team);

// Reachable ground, map context and task views of one round. `view_team` decides view
// requirements and labels (the no-hetero ablation passes the homogeneous team);
// `record_targets` fills RoundInputs::targets (diagnostics).
RoundInputs prepare_round(const PlanRequest& request, const TeamCapabilities& view_team, const PlannerOptions& options,
                          bool record_targets = false);

// Where views may stand: the exploration region (which bounds the targets) widened
// horizontally by its height, at most `max_range_m`. Seeing the top of a facade H above the
// sensor within gamma_th = 45 degrees takes a standoff of at least H; on the default scene the
// site box left 8 m in front of the 14 m main building's south facade and 4 m in front of its
// west facade, so the MR1000 stood on the site's edge and its sweeps of the upper floors failed
// on the angle. An unbounded or empty region is returned as it is.
Eigen::AlignedBox3d stand_region(const Eigen::AlignedBox3d& region, double max_range_m);

// Each robot's graph vertex (RoundInputs::robot_vertices) on the graph of its graph species.
std::vector<std::optional<uint64_t>> robot_vertices(const highlevel::TopologyGraph& graph,
                                                    const std::vector<RobotState>& robots,
                                                    const TeamCapabilities& team);

// Ground vertices each species can drive to from its robots' vertices (see RoundInputs),
// on the terrain of its graph species (TeamCapabilities::graph_species_of).
std::vector<std::unordered_set<uint64_t>> reachable_ground(const highlevel::TopologyGraph& graph,
                                                           const std::vector<RobotState>& robots,
                                                           const std::vector<std::optional<uint64_t>>& robot_vertices,
                                                           const TeamCapabilities& team,
                                                           const Eigen::AlignedBox3d& region);

// Stage timing on the planner's clock (wall time in services, thread CPU time in benchmarks).
class StageClock {
 public:
  explicit StageClock(const PlannerOptions& options);
  // Seconds since the previous lap (or construction).
  double lap();
  double total() const;

 private:
  bool cpu_;
  int64_t start_ns_;
  int64_t last_ns_;
};

}  // namespace hexplore::planning
