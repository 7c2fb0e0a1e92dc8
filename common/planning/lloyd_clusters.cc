#include "common/planning/lloyd_clusters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace hexplore::planning {
namespace {

struct Working : LloydCluster {
  std::unordered_map<uint64_t, double> dist;  // metres from the centre, for its species
  bool stale = true;                          // dist must be recomputed
};

// The vertex a centre snaps to: the species' nearest vertex to the mean when the species
// reaches it, else the member view standing nearest to the mean (always reached).
uint64_t snap(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& mean, int species,
              const std::unordered_set<uint64_t>& reachable, const std::vector<TaskView>& views,
              const std::vector<int>& members) {
  if (const auto v = graph.nearest(mean, species); v && reachable.count(*v)) return *v;
  uint64_t best = views[size_t(members.front())].ground_key;
  double bd = std::numeric_limits<double>::infinity();
  for (int m : members) {
    const double d = (views[size_t(m)].position - mean).norm();
    const uint64_t k = views[size_t(m)].ground_key;
    if (d < bd || (d == bd && k < best)) bd = d, best = k;
  }
  return best;
}

Eigen::Vector3d mean_of(const std::vector<TaskView>& views, const std::vector<int>& members) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int m : members) sum += views[size_t(m)].position;
  return sum / double(members.size());
}

double radius_of(const std::vector<TaskView>& views, const std::vector<int>& members, const Eigen::Vector3d& centre,
                 int* farthest = nullptr) {
  double r = -1.0;
  for (int m : members) {
    const double d = (views[size_t(m)].position - centre).norm();
    if (d > r) {
      r = d;
      if (farthest) *farthest = m;
    }
  }
  return r;
}

}  // namespace

std::vector<LloydCluster> capability_lloyd(const highlevel::TopologyGraph& graph, const std::vector<TaskView>& views,
                                           const std::vector<int>& species_mask, const std::vector<LloydSeed>& seeds,
                                           const std::vector<std::unordered_set<uint64_t>>& reachable,
                                           const std::vector<double>& speed, const LloydOptions& o) {
  std::vector<Working> clusters;
  for (const auto& s : seeds) {
    Working c;
    c.species = s.species;
    c.centre_vertex = s.vertex;
    c.centre = graph.position(s.vertex).value_or(Eigen::Vector3d::Zero());
    clusters.push_back(std::move(c));
  }
  std::vector<int> owner(views.size(), -2);

  auto assign = [&] {
    bool changed = false;
    for (auto& c : clusters) {
      if (c.stale) c.dist = graph.distances_from(c.centre_vertex, c.species), c.stale = false;
      c.members.clear();
    }
    for (size_t v = 0; v < views.size(); ++v) {
      int best = -1;
      double bt = std::numeric_limits<double>::infinity();
      for (size_t c = 0; c < clusters.size(); ++c) {
        const Working& cl = clusters[c];
        if (!(species_mask[v] & (1 << cl.species))) continue;
        const auto it = cl.dist.find(views[v].ground_key);
        if (it == cl.dist.end()) continue;
        const double t = it->second / std::max(1e-6, speed[size_t(cl.species)]);
        if (t < bt) bt = t, best = int(c);  // ties: the earlier cluster
      }
      if (best >= 0) clusters[size_t(best)].members.push_back(int(v));
      changed |= owner[v] != best;
      owner[v] = best;
    }
    return changed;
  };
  auto move_centres = [&] {
    for (auto& c : clusters) {
      if (c.members.empty()) continue;
      const uint64_t v =
          snap(graph, mean_of(views, c.members), c.species, reachable[size_t(c.species)], views, c.members);
      if (v == c.centre_vertex) continue;
      c.centre_vertex = v;
      c.centre = *graph.position(v);
      c.stale = true;
    }
  };

  for (int it = 0; it < o.max_iterations; ++it) {
    bool changed = assign();
    move_centres();
    // Split the clusters wider than the compactness distance (one new centre each).
    const size_t before = clusters.size();
    for (size_t c = 0; c < before; ++c) {
      if (clusters[c].members.size() < 2) continue;
      int far = -1;
      if (radius_of(views, clusters[c].members, mean_of(views, clusters[c].members), &far) <= o.compactness_m) continue;
      Working split;
      split.species = clusters[c].species;
      split.centre_vertex = views[size_t(far)].ground_key;
      split.centre = views[size_t(far)].position;
      clusters.push_back(std::move(split));
      changed = true;
    }
    // Merge pairs of one species that fit within the compactness distance together.
    for (size_t a = 0; a < before; ++a)
      for (size_t b = a + 1; b < before; ++b) {
        Working& ca = clusters[a];
        Working& cb = clusters[b];
        if (ca.species != cb.species || ca.members.empty() || cb.members.empty()) continue;
        std::vector<int> both = ca.members;
        both.insert(both.end(), cb.members.begin(), cb.members.end());
        std::sort(both.begin(), both.end());
        if (radius_of(views, both, mean_of(views, both)) > o.compactness_m) continue;
        ca.members = both;
        cb.members.clear();
        ca.centre_vertex = snap(graph, mean_of(views, both), ca.species, reachable[size_t(ca.species)], views, both);
        ca.centre = *graph.position(ca.centre_vertex);
        ca.stale = true;
        changed = true;
      }
    // Clusters emptied by a merge (or never chosen) stop competing, except the robots' own
    // starting clusters, which stay so that every species keeps a centre near its robots.
    std::vector<Working> kept;
    for (size_t c = 0; c < clusters.size(); ++c)
      if (c < seeds.size() || c >= before || !clusters[c].members.empty()) kept.push_back(std::move(clusters[c]));
    clusters = std::move(kept);
    if (!changed) break;
  }
  assign();  // members consistent with the final centres

  std::vector<LloydCluster> out;
  for (auto& c : clusters)
    if (!c.members.empty()) out.push_back(static_cast<LloydCluster&>(c));
  return out;
}

}  // namespace hexplore::planning
