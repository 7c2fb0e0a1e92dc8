#include "common/planning/cost_model.h"

#include <cmath>


namespace hexplore::planning {

AssignmentInstance build_assignment(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                                    const std::vector<TaskCluster>& clusters, const TeamCapabilities& team,
                                    const std::vector<RobotState>& robots,
                                    const std::vector<std::optional<uint64_t>>& robot_vertices,
                                    const CoverReading* cover) {
  AssignmentInstance out;
  const int S = int(team.species.size());
  const int R = int(robots.size());
  std::vector<char> used(size_t(S), 0);
  for (const auto& r : robots) used[size_t(r.species)] = 1;
  out.speed.resize(size_t(S));
  for (int k = 0; k < S; ++k) out.speed[size_t(k)] = std::max(1e-6, team.species[size_t(k)].speed_mps);

  out.robot_vertex.resize(size_t(R), 0);
  std::vector<char> robot_on_graph(size_t(R), 0);
  for (int r = 0; r < R; ++r)
    if (const auto& v = robot_vertices[size_t(r)]) {
      out.robot_vertex[size_t(r)] = *v;
      robot_on_graph[size_t(r)] = 1;
    }

  // Anchors and execution times per cluster and species.
  const size_t C = clusters.size();
  out.anchor.assign(C, std::vector<uint64_t>(size_t(S), 0));
  std::vector<std::vector<double>> delta(C, std::vector<double>(size_t(S), kInfinity));
  for (size_t c = 0; c < C; ++c) {
    const TaskCluster& cl = clusters[c];
    for (int k = 0; k < S; ++k) {
      if (!used[size_t(k)] || (cl.label != kPublic && cl.label != k)) continue;
      const int g = team.graph_species_of(k);
      const auto a = graph.nearest(cl.center, g);
      if (!a) continue;
      out.anchor[c][size_t(k)] = *a;
      double walk = 0.0;
      for (int v : cl.views) walk += graph.dist(*a, views[size_t(v)].ground_key, g);
      if (!std::isfinite(walk)) continue;
      int dwells = cl.facade_views;
      if (cover) {
        const ClusterWork work = cover_work(cover->context, views, cl, team.species[size_t(k)], cover->options);
        walk = work.walk_m;
        dwells = work.dwells;
      }
      delta[c][size_t(k)] = walk / out.speed[size_t(k)] + dwells / std::max(1e-6, team.species[size_t(k)].observation_speed);
    }
  }
  // Keep clusters that some robot of a matching species can reach.
  for (size_t c = 0; c < C; ++c) {
    bool ok = false;
    for (int r = 0; r < R && !ok; ++r) {
      const int k = robots[size_t(r)].species;
      ok = robot_on_graph[size_t(r)] && std::isfinite(delta[c][size_t(k)]) &&
           std::isfinite(graph.dist(out.robot_vertex[size_t(r)], out.anchor[c][size_t(k)], team.graph_species_of(k)));
    }
    if (ok) out.city_cluster.push_back(int(c));
    else out.dropped.push_back(int(c));
  }

  MtspProblem& p = out.problem;
  const int N = int(out.city_cluster.size());
  p.num_cities = N;
  p.num_species = std::max(1, S);
  p.kind = RouteKind::kOpen;
  for (const auto& r : robots) p.robots.push_back({r.species});
  p.city_species.resize(size_t(N));
  p.positions.resize(size_t(N + R));
  for (int i = 0; i < N; ++i) {
    const TaskCluster& cl = clusters[size_t(out.city_cluster[size_t(i)])];
    p.city_species[size_t(i)] = cl.label;
    p.positions[size_t(i)] = cl.center;
  }
  for (int r = 0; r < R; ++r) p.positions[size_t(N + r)] = robots[size_t(r)].position;
  p.execution.assign(size_t(p.num_species), std::vector<double>(size_t(N), kInfinity));
  p.travel.assign(size_t(p.num_species), CostMatrix());
  for (int k = 0; k < S; ++k) {
    if (!used[size_t(k)]) {
      p.travel[size_t(k)] = CostMatrix(N + R, kInfinity);
      continue;
    }
    for (int i = 0; i < N; ++i) p.execution[size_t(k)][size_t(i)] = delta[size_t(out.city_cluster[size_t(i)])][size_t(k)];
    CostMatrix m(N + R, kInfinity);
    // Node n's vertex for species k: a cluster anchor or a robot's depot vertex (robots of
    // other species stand on vertices that may not be passable for k: leave those at +inf).
    auto vertex = [&](int n, uint64_t& key) {
      if (n < N) {
        key = out.anchor[size_t(out.city_cluster[size_t(n)])][size_t(k)];
        return std::isfinite(delta[size_t(out.city_cluster[size_t(n)])][size_t(k)]);
      }
      key = out.robot_vertex[size_t(n - N)];
      return robots[size_t(n - N)].species == k && robot_on_graph[size_t(n - N)] != 0;
    };
    for (int a = 0; a < N + R; ++a) {
      uint64_t ka;
      if (!vertex(a, ka)) continue;
      for (int b = 0; b < N + R; ++b) {
        uint64_t kb;
        if (a == b) {
          m.set(a, b, 0.0);
          continue;
        }
        if (b >= N || !vertex(b, kb)) continue;  // nobody travels into a depot (open routes)
        m.set(a, b, graph.dist(ka, kb, team.graph_species_of(k)) / out.speed[size_t(k)]);
      }
    }
    p.travel[size_t(k)] = std::move(m);
  }
  return out;
}

}  // namespace hexplore::planning
