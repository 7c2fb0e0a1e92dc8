#pragma once
// MROMT+'s candidate views (BASELINES.md): the round's task views plus, as MNSS builds its
// candidates, views on the ground within a radius of a task view; each records the ISE
// supervoxels (targets of the nearby task views) it sees, so a priority queue can score
// them and co-visibility can prune them. A ground spot gives one candidate per observation
// level at which it sees more (a long-range robot standing there sees farther facades).

#include <unordered_set>
#include <vector>

#include "common/planning/capabilities.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct CandidateView {
  TaskView view;          // position, ground, requirements; targets = the ISE it sees, ascending
  double quality = 0.0;   // summed visibility score over its targets (tie-break of equal counts)
  bool task_view = false; // one of the round's task views (else made on nearby ground)
  int species_mask = 0;   // bit k: species k may take it (requirements met, ground reached)
};

// Candidates with at least one target that some species may take, ordered by (ground key,
// observation requirement, task views first, key). `reachable` is RoundInputs::reachable.
std::vector<CandidateView> candidate_views(const MapContext& ctx, const std::vector<TaskView>& views,
                                           const TeamCapabilities& team, const PlannerOptions& o, double radius,
                                           const std::vector<std::unordered_set<uint64_t>>& reachable);

}  // namespace hexplore::planning
