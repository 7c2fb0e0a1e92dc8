#include "common/planning/mnss.h"

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "common/planning/frontier.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {

double tour_length(const std::vector<TaskView>& views, const Eigen::Vector3d& start,
                   const std::optional<Eigen::Vector3d>& end) {
  double len = 0.0;
  Eigen::Vector3d prev = start;
  for (const auto& v : views) {
    len += (v.position - prev).norm();
    prev = v.position;
  }
  if (end) len += (*end - prev).norm();
  return len;
}

std::vector<TaskView> order_views(std::vector<TaskView> views, const Eigen::Vector3d& start,
                                  const std::optional<Eigen::Vector3d>& end) {
  const size_t n = views.size();
  if (n <= 1) return views;
  // Nearest neighbour from the start (ties: smaller key, for determinism).
  std::vector<TaskView> ordered;
  ordered.reserve(n);
  std::vector<char> used(n, 0);
  Eigen::Vector3d at = start;
  for (size_t step = 0; step < n; ++step) {
    size_t best = n;
    double bd = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i) {
      if (used[i]) continue;
      const double d = (views[i].position - at).norm();
      if (d < bd || (d == bd && views[i].key < views[best].key)) bd = d, best = i;
    }
    used[best] = 1;
    ordered.push_back(views[best]);
    at = views[best].position;
  }
  // 2-opt on the open path with fixed start (and end when given).
  auto pos = [&](long i) -> Eigen::Vector3d {
    if (i < 0) return start;
    if (size_t(i) >= n) return *end;
    return ordered[size_t(i)].position;
  };
  bool improved = true;
  for (int pass = 0; improved && pass < 50; ++pass) {
    improved = false;
    for (long i = 0; i + 1 < long(n); ++i)
      for (long j = i + 1; j < long(n); ++j) {
        const bool has_next = size_t(j + 1) < n || end.has_value();
        double delta = (pos(i - 1) - pos(j)).norm() - (pos(i - 1) - pos(i)).norm();
        if (has_next) delta += (pos(i) - pos(j + 1)).norm() - (pos(j) - pos(j + 1)).norm();
        if (delta < -1e-9) {
          std::reverse(ordered.begin() + i, ordered.begin() + j + 1);
          improved = true;
        }
      }
  }
  return ordered;
}

std::vector<TaskView> mnss_tour(const MapContext& ctx, const std::vector<TaskView>& views,
                                const std::vector<int>& view_indices, const std::vector<Eigen::Vector3d>& neighbourhood,
                                double radius, const SpeciesCapability& species, const Eigen::Vector3d& start,
                                const std::optional<Eigen::Vector3d>& end, const PlannerOptions& o, core::PlanRng& rng,
                                TourStats* stats, const std::unordered_set<uint64_t>* reachable) {
  TourStats local;
  TourStats& st = stats ? *stats : local;
  // Targets: the cluster's ISE supervoxels, with the task view that was made for each.
  std::vector<const highlevel::Supervoxel*> targets;
  std::vector<int> target_view;
  for (int v : view_indices)
    for (uint64_t t : views[size_t(v)].targets)
      if (const auto* sv = ctx.map.find(t)) {
        targets.push_back(sv);
        target_view.push_back(v);
      }
  st.targets = int(targets.size());
  // Candidates: nearby ground the species may stand on.
  std::vector<const highlevel::Supervoxel*> candidates;
  std::unordered_set<uint64_t> have;
  auto add = [&](const highlevel::Supervoxel* g) {
    if (g->traversal_requirement > species.traversal_level || (reachable && !reachable->count(g->key))) return;
    if (have.insert(g->key).second) candidates.push_back(g);
  };
  for (const auto& p : neighbourhood)
    for (const auto* g : ctx.ground.within(p, radius)) add(g);
  for (int v : view_indices)  // the set's own views always stand on candidates
    if (const auto* g = ctx.map.find(views[size_t(v)].ground_key)) add(g);
  st.candidates = int(candidates.size());

  // Score matrix (sparse): for each candidate, the targets it sees and the summed score.
  const size_t T = targets.size();
  std::vector<std::vector<std::pair<int, double>>> sees(candidates.size());
  std::vector<std::vector<int>> seen_by(T);
  for (size_t c = 0; c < candidates.size(); ++c) {
    const auto* g = candidates[c];
    for (size_t t = 0; t < T; ++t) {
      if (ctx.tried_from(targets[t]->key, g->center)) continue;
      const double score = ground_view_score(ctx.map, *g, *targets[t], species.observation_range_m, ctx.occlusion, o, st.rays);
      if (score <= 0.0) continue;
      sees[c].push_back({int(t), score});
      seen_by[t].push_back(int(c));
    }
  }
  std::vector<TaskView> mandatory;  // original views of targets no candidate sees
  std::vector<char> coverable(T, 1);
  for (size_t t = 0; t < T; ++t)
    if (seen_by[t].empty()) {
      coverable[t] = 0;
      ++st.uncoverable;
      const TaskView& v = views[size_t(target_view[t])];
      if (std::none_of(mandatory.begin(), mandatory.end(), [&](const TaskView& m) { return m.key == v.key; }))
        mandatory.push_back(v);
    }

  auto make_view = [&](size_t c, const std::vector<char>& covered_now) {
    const auto* g = candidates[c];
    TaskView v;
    v.key = g->key;
    v.ground_key = g->key;
    v.position = g->center;
    v.look_at = g->center;
    v.traversal_requirement = g->traversal_requirement;
    double best = -1.0;
    for (const auto& [t, s] : sees[c]) {
      if (!covered_now[size_t(t)]) continue;
      v.targets.push_back(targets[size_t(t)]->key);
      v.frontier = v.frontier || at_frontier(ctx.map, *targets[size_t(t)], o.region);  // false for facades
      if (targets[size_t(t)]->facade() && s > best) {
        best = s;
        v.look_at = targets[size_t(t)]->center;
        v.facade = true;
        v.score = s;
      }
    }
    return v;
  };

  std::vector<TaskView> best_tour;
  double best_cost = std::numeric_limits<double>::infinity();
  const double min_sep2 = o.min_view_separation_m * o.min_view_separation_m;
  for (int sample = 0; sample < std::max(1, o.mnss_samples); ++sample) {
    std::vector<char> covered(T, 0);
    std::vector<size_t> chosen;
    std::vector<TaskView> picked = mandatory;
    size_t remaining = 0;
    for (size_t t = 0; t < T; ++t) remaining += coverable[t];
    while (remaining > 0) {
      // A random uncovered target, then a view that sees it, drawn with probability
      // proportional to its score over the still-uncovered targets.
      std::vector<size_t> open;
      for (size_t t = 0; t < T; ++t)
        if (coverable[t] && !covered[t]) open.push_back(t);
      const size_t t = open[size_t(rng.index(open.size()))];
      std::vector<std::pair<int, double>> weights;
      double total = 0.0;
      for (int pass = 0; pass < 2 && weights.empty(); ++pass)
        for (int c : seen_by[t]) {
          bool near = false;
          for (size_t q : chosen)
            near |= (candidates[size_t(c)]->center - candidates[q]->center).squaredNorm() < min_sep2;
          if (near && pass == 0) continue;  // MNSS rejects views next to a chosen one
          double w = 0.0;
          for (const auto& [u, s] : sees[size_t(c)])
            if (!covered[size_t(u)]) w += s;
          weights.push_back({c, w});
          total += w;
        }
      double draw = rng.uniform() * total;
      int pick = weights.back().first;
      for (const auto& [c, w] : weights) {
        if (draw < w) {
          pick = c;
          break;
        }
        draw -= w;
      }
      std::vector<char> newly(T, 0);
      for (const auto& [u, s] : sees[size_t(pick)])
        if (!covered[size_t(u)]) {
          covered[size_t(u)] = 1;
          newly[size_t(u)] = 1;
          --remaining;
        }
      chosen.push_back(size_t(pick));
      picked.push_back(make_view(size_t(pick), newly));
    }
    std::vector<TaskView> tour = order_views(std::move(picked), start, end);
    int facade = 0;
    for (const auto& v : tour) facade += v.facade ? 1 : 0;
    const double cost = tour_length(tour, start, end) / std::max(1e-6, species.speed_mps) +
                        facade / std::max(1e-6, species.observation_speed);
    if (cost < best_cost) {
      best_cost = cost;
      best_tour = std::move(tour);
    }
  }
  return best_tour;
}

}  // namespace hexplore::planning
