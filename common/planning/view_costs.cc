#include "common/planning/view_costs.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/planning/labels.h"

namespace hexplore::planning {

bool species_can_take(const TaskView& view, const SpeciesCapability& species,
                      const std::unordered_set<uint64_t>& reachable) {
  return matches(view.observation_requirement, view.traversal_requirement, species) &&
         reachable.count(view.ground_key) != 0;
}

double observation_time_s(const TaskView& view, const SpeciesCapability& species) {
  return view.facade ? 1.0 / std::max(1e-6, species.observation_speed) : 0.0;
}

ViewCosts build_view_costs(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                           const TeamCapabilities& team, const std::vector<RobotState>& robots,
                           const std::vector<std::optional<uint64_t>>& robot_vertices,
                           const std::vector<std::unordered_set<uint64_t>>& reachable) {
  ViewCosts out;
  const int S = int(team.species.size());
  const int R = int(robots.size());
  std::vector<char> used(size_t(S), 0);
  for (const auto& r : robots) {
    used[size_t(r.species)] = 1;
    out.robot_species.push_back(r.species);
  }
  out.robot_vertex = robot_vertices;
  out.speed.resize(size_t(S));
  for (int k = 0; k < S; ++k) out.speed[size_t(k)] = std::max(1e-6, team.species[size_t(k)].speed_mps);

  // Which species may take each view; views no species of the team's robots may take are out.
  for (size_t v = 0; v < views.size(); ++v) {
    int mask = 0;
    for (int k = 0; k < S; ++k)
      if (used[size_t(k)] && size_t(k) < reachable.size() &&
          species_can_take(views[v], team.species[size_t(k)], reachable[size_t(k)]))
        mask |= 1 << k;
    if (mask == 0) {
      out.unservable.push_back(int(v));
      continue;
    }
    out.view_of_node.push_back(int(v));
    out.node_species_mask.push_back(mask);
  }
  const int N = out.nodes();

  out.travel.assign(size_t(S), CostMatrix());
  out.service.assign(size_t(S), std::vector<double>(size_t(N), kInfinity));
  for (int k = 0; k < S; ++k) {
    if (!used[size_t(k)]) continue;
    const SpeciesCapability& sp = team.species[size_t(k)];
    const double speed = out.speed[size_t(k)];
    // Nodes species k may take, grouped by the ground vertex they stand on (views often
    // share one): one Dijkstra per distinct vertex.
    std::map<uint64_t, std::vector<int>> by_vertex;
    for (int n = 0; n < N; ++n) {
      if (!(out.node_species_mask[size_t(n)] & (1 << k))) continue;
      out.service[size_t(k)][size_t(n)] = observation_time_s(views[size_t(out.view_of_node[size_t(n)])], sp);
      by_vertex[views[size_t(out.view_of_node[size_t(n)])].ground_key].push_back(n);
    }
    CostMatrix m(N + R, kInfinity);
    // One cached Dijkstra per source vertex; dist() then reads it (cheaper than copying
    // distances_from's map, measured on bench_planning_round's map).
    auto fill_row = [&](uint64_t source, const std::vector<int>& rows) {
      for (const auto& [target, columns] : by_vertex) {
        const double d = graph.dist(source, target, k);
        if (!std::isfinite(d)) continue;
        const double t = d / speed;
        for (int a : rows)
          for (int b : columns) m.set(a, b, a == b ? 0.0 : t);
      }
    };
    for (const auto& [vertex, nodes] : by_vertex) fill_row(vertex, nodes);
    for (int r = 0; r < R; ++r) {
      if (robots[size_t(r)].species != k || !out.robot_vertex[size_t(r)]) continue;
      m.set(N + r, N + r, 0.0);
      fill_row(*out.robot_vertex[size_t(r)], {N + r});
    }
    out.travel[size_t(k)] = std::move(m);
  }

  out.eligible.assign(size_t(R), std::vector<char>(size_t(N), 0));
  for (int r = 0; r < R; ++r) {
    const int k = robots[size_t(r)].species;
    if (!out.robot_vertex[size_t(r)]) continue;
    for (int n = 0; n < N; ++n)
      out.eligible[size_t(r)][size_t(n)] =
          std::isfinite(out.service[size_t(k)][size_t(n)]) && std::isfinite(out.travel[size_t(k)](N + r, n));
  }
  // A node that only robots cut off from it could take is not servable after all.
  std::vector<int> keep;
  for (int n = 0; n < N; ++n) {
    bool any = false;
    for (int r = 0; r < R && !any; ++r) any = out.eligible[size_t(r)][size_t(n)] != 0;
    if (any) keep.push_back(n);
  }
  if (int(keep.size()) == N) return out;
  // Rare (a species whose robots stand in different components): rebuild without them.
  std::vector<TaskView> servable;
  std::vector<int> original;
  for (int n : keep) {
    servable.push_back(views[size_t(out.view_of_node[size_t(n)])]);
    original.push_back(out.view_of_node[size_t(n)]);
  }
  std::vector<int> unservable = out.unservable;
  for (int n = 0; n < N; ++n)
    if (!std::binary_search(keep.begin(), keep.end(), n)) unservable.push_back(out.view_of_node[size_t(n)]);
  // Only views reachable from some robot are left, so this recursion ends after one step.
  ViewCosts again = build_view_costs(graph, servable, team, robots, robot_vertices, reachable);
  for (int& v : again.view_of_node) v = original[size_t(v)];
  for (int v : again.unservable) unservable.push_back(original[size_t(v)]);
  std::sort(unservable.begin(), unservable.end());
  again.unservable = std::move(unservable);
  return again;
}

}  // namespace hexplore::planning
