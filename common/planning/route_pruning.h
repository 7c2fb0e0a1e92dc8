#pragma once
// The minimal view set over a whole route. MNSS (mnss.h) picks a minimal set of views per
// task cluster, for that cluster's targets only; but a facade view sees far beyond its cluster
// (clusters are 5 m of view positions, the MR1000's range is 27 m), so a route built cluster by
// cluster stops again and again where one stop would see the same targets: on the default
// scene the MR1000's routes held 100-170 views of 1-7 targets each, each a 10 s dwell, along
// one side of the site (common/planning/README.md, "One view for what one stop sees").
// prune_route drops every view whose targets other views of the same route see (the view test
// J for the species' range and line of sight; ground within the composite radius), and hands
// those targets to a view that is kept. The order of the kept views is the route's.

#include <vector>

#include "common/planning/capabilities.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct RoutePruneStats {
  int views_before = 0;
  int views_after = 0;
  int targets = 0;
  int64_t rays = 0;
};

// Views are tried for dropping from the one that sees the fewest of the route's targets up
// (ties: the later one first), so views that see much are kept. A dropped view's targets go
// to the kept view that sees the most of the route's targets among those that see each.
std::vector<TaskView> prune_route(const MapContext& ctx, std::vector<TaskView> route, const SpeciesCapability& species,
                                  const PlannerOptions& o, RoutePruneStats* stats = nullptr);

}  // namespace hexplore::planning
