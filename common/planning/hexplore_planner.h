#pragma once
// The paper's planner and its ablations as one pipeline with switches: task views ->
// clustering -> HMDMTSP assignment (GA) -> MNSS tours -> executable path.

#include <string>
#include <unordered_set>

#include "common/planning/planner.h"

namespace hexplore::planning {

enum class Ablation {
  kNone,       // "hexplore": the full method
  kNoHetero,   // all robots assumed as capable as the weakest
  kNoCluster,  // every view its own cluster, no MNSS
  kNoMnss,     // tour over all views of a cluster instead of MNSS
  kNoAssign,   // Voronoi partition of views by graph distance, MNSS kept, no clustering / GA
};

class HexplorePlanner : public Planner {
 public:
  explicit HexplorePlanner(Ablation ablation = Ablation::kNone) : ablation_(ablation) {}
  std::string name() const override;
  void configure(const PlannerContext& context) override;
  PlanResult plan(const PlanRequest& request) override;

 private:
  PlanResult plan_voronoi(const PlanRequest& request, const TeamCapabilities& team);
  Ablation ablation_;
  PlannerContext context_;
  bool configured_ = false;
};

// The executable path from `from` to the goal view along the topology graph for a species,
// through each vertex's clearance waypoint (TopologyGraph::waypoint) and preferring vertices
// with room for the body (clearance costs, when the graph has body radii).
// `avoid` (optional): vertices the robot found it cannot pass (blocked there); the path goes
// around them, or is invalid when it cannot.
ExecutablePlan executable_path(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& from, int species,
                               const TaskView& goal, const std::unordered_set<uint64_t>* avoid = nullptr);

}  // namespace hexplore::planning
