#pragma once
// The paper's planner and its ablations as one pipeline with switches: task views ->
// clustering -> HMDMTSP assignment (GA) -> MNSS tours -> executable path.

#include <string>

#include "common/planning/planner_base.h"

namespace hexplore::planning {

enum class Ablation {
  kNone,       // "hexplore": the full method
  kNoHetero,   // all robots assumed as capable as the weakest
  kNoCluster,  // every view its own cluster, no MNSS
  kNoMnss,     // tour over all views of a cluster instead of MNSS
  kNoAssign,   // Voronoi partition of views by graph distance, MNSS kept, no clustering / GA
};

class HexplorePlanner : public ConfiguredPlanner {
 public:
  explicit HexplorePlanner(Ablation ablation = Ablation::kNone) : ablation_(ablation) {}
  std::string name() const override;
  PlanResult plan(const PlanRequest& request) override;

 private:
  PlanResult plan_voronoi(const PlanRequest& request, const TeamCapabilities& team, const PlannerOptions& options) const;
  Ablation ablation_;
};

}  // namespace hexplore::planning
