#include "common/planning/executable_path.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

#include "common/planning/robot_vertex.h"

namespace hexplore::planning {
namespace {

// Shortest path a -> b for a species that never enters `avoid` (Dijkstra with a heap).
std::vector<uint64_t> path_avoiding(const highlevel::TopologyGraph& graph, uint64_t a, uint64_t b, int species,
                                    const std::unordered_set<uint64_t>& avoid) {
  using Item = std::pair<double, uint64_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  std::unordered_map<uint64_t, double> dist{{a, 0.0}};
  std::unordered_map<uint64_t, uint64_t> parent;
  open.push({0.0, a});
  while (!open.empty()) {
    const auto [d, k] = open.top();
    open.pop();
    if (d > dist[k]) continue;
    if (k == b) break;
    for (const auto& [n, w] : graph.neighbours(k)) {
      if (avoid.count(n) || !graph.passable(n, species)) continue;
      const double nd = d + w + graph.clearance_penalty(n, species);
      const auto it = dist.find(n);
      if (it != dist.end() && it->second <= nd) continue;
      dist[n] = nd;
      parent[n] = k;
      open.push({nd, n});
    }
  }
  if (!dist.count(b)) return {};
  std::vector<uint64_t> keys{b};
  while (keys.back() != a) keys.push_back(parent.at(keys.back()));
  std::reverse(keys.begin(), keys.end());
  return keys;
}

}  // namespace

ExecutablePlan executable_path(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& from, int species,
                               const TaskView& goal, const std::unordered_set<uint64_t>* avoid) {
  ExecutablePlan out;
  out.goal = goal;
  auto start = robot_vertex(graph, from, species);
  if (!start) return out;
  const bool avoiding = avoid && !avoid->empty();
  if (avoiding && avoid->count(goal.ground_key)) return out;
  if (avoiding && avoid->count(*start)) {
    // Standing next to a vertex we cannot pass: leave from the nearest neighbour we can.
    std::optional<uint64_t> best;
    double bd = std::numeric_limits<double>::infinity();
    for (const auto& [n, w] : graph.neighbours(*start)) {
      const auto p = graph.position(n);
      if (avoid->count(n) || !graph.passable(n, species) || !p) continue;
      const double d = (*p - from).norm();
      if (d < bd) bd = d, best = n;
    }
    if (!best) return out;
    start = best;
  }
  const auto keys = avoiding ? path_avoiding(graph, *start, goal.ground_key, species, *avoid)
                             : graph.path(*start, goal.ground_key, species);
  if (keys.empty()) return out;
  // Through each vertex where the species' body clears the obstacles the map knows around it.
  for (uint64_t k : keys)
    if (auto p = graph.waypoint(k, species)) {
      out.waypoints.push_back(*p);
      out.keys.push_back(k);
    }
  out.valid = true;
  return out;
}

}  // namespace hexplore::planning
