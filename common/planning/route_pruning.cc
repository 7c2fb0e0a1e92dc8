#include "common/planning/route_pruning.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "common/planning/frontier.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {

std::vector<TaskView> prune_route(const MapContext& ctx, std::vector<TaskView> route, const SpeciesCapability& species,
                                  const PlannerOptions& o, RoutePruneStats* stats) {
  RoutePruneStats local;
  RoutePruneStats& st = stats ? *stats : local;
  st = {};
  st.views_before = int(route.size());

  // The route's targets, each once.
  std::vector<const highlevel::Supervoxel*> targets;
  std::unordered_map<uint64_t, int> target_index;
  for (const TaskView& v : route)
    for (uint64_t t : v.targets)
      if (const auto* sv = ctx.map.find(t); sv && target_index.emplace(t, int(targets.size())).second)
        targets.push_back(sv);
  st.targets = int(targets.size());

  // What each view sees of them: its own targets (MNSS chose it for them), facade targets that
  // pass J from where it stands, ground targets within the composite radius.
  const size_t V = route.size(), T = targets.size();
  std::vector<std::vector<int>> sees(V), seen_by(T);
  for (size_t v = 0; v < V; ++v) {
    std::vector<char> mark(T, 0);
    for (uint64_t t : route[v].targets)
      if (auto it = target_index.find(t); it != target_index.end()) mark[size_t(it->second)] = 1;
    const highlevel::Supervoxel* ground = ctx.map.find(route[v].ground_key);
    if (ground != nullptr)
      for (size_t t = 0; t < T; ++t)
        if (!mark[t] && !ctx.tried_from(targets[t]->key, ground->center))
          mark[t] = ground_view_score(ctx.map, *ground, *targets[t], species.observation_range_m, ctx.occlusion, o, st.rays) > 0.0;
    for (size_t t = 0; t < T; ++t)
      if (mark[t]) {
        sees[v].push_back(int(t));
        seen_by[t].push_back(int(v));
      }
  }

  // Drop views whose own targets a kept view also sees, fewest-seeing first.
  std::vector<size_t> order(V);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return sees[a].size() != sees[b].size() ? sees[a].size() < sees[b].size() : a > b;
  });
  std::vector<char> kept(V, 1);
  auto best_keeper = [&](int t, size_t except) {
    int best = -1;
    for (int u : seen_by[size_t(t)])
      if (size_t(u) != except && kept[size_t(u)] && (best < 0 || sees[size_t(u)].size() > sees[size_t(best)].size()))
        best = u;
    return best;
  };
  for (size_t v : order) {
    std::vector<std::pair<int, int>> handover;  // (target, keeper)
    bool droppable = true;
    for (uint64_t key : route[v].targets) {
      const auto it = target_index.find(key);
      if (it == target_index.end()) continue;
      const int keeper = best_keeper(it->second, v);
      if (keeper < 0) {
        droppable = false;
        break;
      }
      handover.push_back({it->second, keeper});
    }
    if (!droppable) continue;
    kept[v] = 0;
    for (const auto& [t, keeper] : handover) {
      TaskView& k = route[size_t(keeper)];
      const highlevel::Supervoxel* sv = targets[size_t(t)];
      if (std::find(k.targets.begin(), k.targets.end(), sv->key) != k.targets.end()) continue;
      k.targets.push_back(sv->key);
      k.frontier = k.frontier || at_frontier(ctx.map, *sv, o.region);  // false for facades
      if (sv->facade() && !k.facade) {  // a ground view that now observes a facade stops there
        k.facade = true;
        k.look_at = sv->center;
      }
    }
  }

  std::vector<TaskView> out;
  out.reserve(V);
  for (size_t v = 0; v < V; ++v)
    if (kept[v]) out.push_back(std::move(route[v]));
  st.views_after = int(out.size());
  return out;
}

}  // namespace hexplore::planning
