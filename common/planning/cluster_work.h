#pragma once
// What executing one task cluster costs a species: the walk and the dwells inside the cluster
// that the execution time delta(tau, k) of the cost model (paper eq. 4-xx-delta) charges.
//
// Two readings:
// - every view (the paper's formula as written): a walk from the cluster's anchor to each of
//   its views, summed, and a dwell at each facade task view. Right for tours that visit every
//   view (the no-mnss ablation, TSPGA+).
// - cover: the views hexplore's tour will stand at. MNSS keeps a set of views that together see
//   the cluster's targets, and a dwell there observes several targets at once (the paper's
//   vartheta_varsigma is "facade task views covered per unit time"). Here: a greedy cover of the
//   cluster's targets by the cluster's own views, a dwell at each facade view of it, and the
//   walk from the cluster centre through them in tour order. On the default mission the every-
//   view reading charged 7-10 times the time of the tours the robots drove, so the balance term
//   of the fitness weighed phantom work and inter-cluster travel hardly counted
//   (common/planning/README.md, "What a cluster costs").

#include <vector>

#include "common/planning/capabilities.h"
#include "common/planning/clustering.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct ClusterWork {
  double walk_m = 0.0;  // metres driven inside the cluster
  int dwells = 0;       // facade views stood at (each 1 / vartheta_varsigma seconds)
};

// The cover reading for a robot of `species` (its observation range; views it may not stand on
// are not candidates). Targets no candidate sees keep their own view, as MNSS keeps them.
ClusterWork cover_work(const MapContext& ctx, const std::vector<TaskView>& views, const TaskCluster& cluster,
                       const SpeciesCapability& species, const PlannerOptions& options);

}  // namespace hexplore::planning
