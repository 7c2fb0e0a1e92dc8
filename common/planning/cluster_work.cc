#include "common/planning/cluster_work.h"

#include <unordered_set>

#include "common/planning/mnss.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {

ClusterWork cover_work(const MapContext& ctx, const std::vector<TaskView>& views, const TaskCluster& cluster,
                       const SpeciesCapability& species, const PlannerOptions& options) {
  // Targets: every ISE supervoxel the cluster's views were made for (own and composite).
  std::vector<const highlevel::Supervoxel*> targets;
  std::vector<size_t> made_by;  // per target: the position in cluster.views of the view made for it
  std::unordered_set<uint64_t> have;
  for (size_t c = 0; c < cluster.views.size(); ++c)
    for (uint64_t t : views[size_t(cluster.views[c])].targets)
      if (const auto* sv = ctx.map.find(t); sv && have.insert(t).second) {
        targets.push_back(sv);
        made_by.push_back(c);
      }

  // Which targets each of the cluster's views sees for this species.
  const size_t T = targets.size();
  std::vector<std::vector<int>> sees(cluster.views.size());
  std::vector<char> seen(T, 0);
  int64_t rays = 0;
  for (size_t c = 0; c < cluster.views.size(); ++c) {
    const TaskView& view = views[size_t(cluster.views[c])];
    const auto* ground = ctx.map.find(view.ground_key);
    if (!ground || ground->traversal_requirement > species.traversal_level) continue;
    for (size_t t = 0; t < T; ++t) {
      if (ctx.tried_from(targets[t]->key, ground->center)) continue;
      if (ground_view_score(ctx.map, *ground, *targets[t], species.observation_range_m, ctx.occlusion, options, rays) <= 0.0)
        continue;
      sees[c].push_back(int(t));
      seen[t] = 1;
    }
  }

  // Greedy cover: the view that sees most still-uncovered targets (ties: the earlier view, so
  // every robot computes the same), until nothing more is gained. Unseen targets keep their view.
  std::vector<char> covered(T, 0);
  std::vector<char> picked(cluster.views.size(), 0);
  std::vector<TaskView> stops;
  ClusterWork work;
  for (;;) {
    size_t best = 0;
    int gain = 0;
    for (size_t c = 0; c < sees.size(); ++c) {
      int g = 0;
      for (int t : sees[c]) g += covered[size_t(t)] ? 0 : 1;
      if (g > gain) gain = g, best = c;
    }
    if (gain == 0) break;
    bool facade = false;  // a stop is a dwell when it newly covers a facade target (as MNSS's views)
    for (int t : sees[best]) {
      facade |= !covered[size_t(t)] && targets[size_t(t)]->facade();
      covered[size_t(t)] = 1;
    }
    work.dwells += facade ? 1 : 0;
    picked[best] = 1;
    stops.push_back(views[size_t(cluster.views[best])]);
  }
  for (size_t t = 0; t < T; ++t) {
    const size_t c = made_by[t];
    if (seen[t] || picked[c]) continue;
    picked[c] = 1;
    stops.push_back(views[size_t(cluster.views[c])]);
    work.dwells += stops.back().facade ? 1 : 0;
  }

  work.walk_m = tour_length(order_views(std::move(stops), cluster.center, std::nullopt), cluster.center, std::nullopt);
  return work;
}

}  // namespace hexplore::planning
