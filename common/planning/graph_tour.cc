#include "common/planning/graph_tour.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace hexplore::planning {

GraphTour graph_tour(const highlevel::TopologyGraph& graph, uint64_t start, const std::vector<uint64_t>& stops,
                     int species, std::optional<uint64_t> end) {
  GraphTour out;
  const int n = int(stops.size());
  if (n == 0) return out;
  // Node 0 is the start, node i + 1 stop i, node n + 1 the end (if any); one search per
  // distinct vertex a leg leaves from (the end is only arrived at), stopping once it has
  // settled every stop.
  const int nodes = n + 2;
  const int end_node = n + 1;
  std::vector<uint64_t> key(static_cast<size_t>(nodes), 0);
  key[0] = start;
  for (int i = 0; i < n; ++i) key[size_t(i) + 1] = stops[size_t(i)];
  if (end) key[size_t(end_node)] = *end;
  std::map<uint64_t, std::vector<int>> sources, targets;
  for (int i = 0; i <= n; ++i) sources[key[size_t(i)]].push_back(i);
  for (int i = 1; i <= n + (end ? 1 : 0); ++i) targets[key[size_t(i)]].push_back(i);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> d(size_t(nodes), std::vector<double>(size_t(nodes), inf));
  std::vector<uint64_t> target_keys;
  for (const auto& [target, columns] : targets) target_keys.push_back(target);
  for (const auto& [source, rows] : sources) {
    const std::vector<double> dist = graph.distances_to(source, target_keys, species);
    size_t t = 0;
    for (const auto& [target, columns] : targets) {
      const double len = dist[t++];
      if (len == highlevel::TopologyGraph::kUnreachable) continue;
      for (int a : rows)
        for (int b : columns) d[size_t(a)][size_t(b)] = len;
    }
  }

  // An end the start cannot reach (another part of the graph) is left out.
  const bool use_end = end && std::isfinite(d[0][size_t(end_node)]);
  std::vector<int> reachable, cut_off;
  for (int i = 1; i <= n; ++i) (std::isfinite(d[0][size_t(i)]) ? reachable : cut_off).push_back(i);
  // Nearest neighbour (ties: the earlier stop).
  std::vector<int> path;
  std::vector<char> used(size_t(n) + 1, 0);
  int at = 0;
  for (size_t step = 0; step < reachable.size(); ++step) {
    int best = -1;
    for (int i : reachable)
      if (!used[size_t(i)] && (best < 0 || d[size_t(at)][size_t(i)] < d[size_t(at)][size_t(best)])) best = i;
    used[size_t(best)] = 1;
    path.push_back(best);
    at = best;
  }
  auto length = [&](const std::vector<int>& p) {
    double len = 0.0;
    int prev = 0;
    for (int i : p) {
      len += d[size_t(prev)][size_t(i)];
      prev = i;
    }
    if (use_end && std::isfinite(d[size_t(prev)][size_t(end_node)])) len += d[size_t(prev)][size_t(end_node)];
    return len;
  };
  // 2-opt and or-opt (1-3 stops, either direction) on the open path, first improvement.
  double best_len = length(path);
  const int m = int(path.size());
  for (bool improved = true; improved;) {
    improved = false;
    for (int i = 0; i < m && !improved; ++i)
      for (int j = i + 1; j < m && !improved; ++j) {
        std::vector<int> p = path;
        std::reverse(p.begin() + i, p.begin() + j + 1);
        if (const double l = length(p); l < best_len - 1e-9) path = std::move(p), best_len = l, improved = true;
      }
    for (int len = 1; len <= 3 && !improved; ++len)
      for (int i = 0; i + len <= m && !improved; ++i)
        for (int to = 0; to <= m - len && !improved; ++to) {
          if (to == i) continue;
          for (bool rev : {false, true}) {
            if (rev && len == 1) continue;
            std::vector<int> seg(path.begin() + i, path.begin() + i + len);
            if (rev) std::reverse(seg.begin(), seg.end());
            std::vector<int> p(path.begin(), path.begin() + i);
            p.insert(p.end(), path.begin() + i + len, path.end());
            p.insert(p.begin() + to, seg.begin(), seg.end());
            if (const double l = length(p); l < best_len - 1e-9) {
              path = std::move(p), best_len = l, improved = true;
              break;
            }
          }
        }
  }
  for (int i : path) out.order.push_back(i - 1);
  for (int i : cut_off) out.order.push_back(i - 1);
  out.length_m = cut_off.empty() ? best_len : inf;
  return out;
}

std::vector<TaskView> order_views_on_graph(const highlevel::TopologyGraph& graph, uint64_t start,
                                           const std::vector<TaskView>& views, int species, std::optional<uint64_t> end) {
  if (views.size() <= 1) return views;
  std::vector<uint64_t> stops;
  stops.reserve(views.size());
  for (const auto& v : views) stops.push_back(v.ground_key);
  std::vector<TaskView> ordered;
  ordered.reserve(views.size());
  for (int i : graph_tour(graph, start, stops, species, end).order) ordered.push_back(views[size_t(i)]);
  return ordered;
}

}  // namespace hexplore::planning
