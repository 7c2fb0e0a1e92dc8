#include "common/highlevel/topology_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>

#include "common/core/seed_key.h"

namespace hexplore::highlevel {
namespace {

uint64_t cache_key(int source, int species) {
  return (static_cast<uint64_t>(source) << 16) | static_cast<uint64_t>(species);
}

}  // namespace

TopologyGraph::TopologyGraph(std::vector<int> species_levels) : levels_(std::move(species_levels)) {
  if (levels_.empty()) throw std::invalid_argument("TopologyGraph: at least one species level is needed");
}

int TopologyGraph::index_of(uint64_t key) const {
  auto it = index_.find(key);
  return it == index_.end() ? -1 : it->second;
}

void TopologyGraph::changed() {
  ++version_;
  std::lock_guard lock(cache_.mutex);
  cache_.searches.clear();
  cache_.bytes = 0;
}

void TopologyGraph::grid_insert(int index) {
  const auto cell = core::cell_of(vertices_[index].position, grid_cell_m_);
  grid_[core::seed_key(cell)].push_back(index);
}

void TopologyGraph::grid_erase(int index) {
  const auto cell = core::cell_of(vertices_[index].position, grid_cell_m_);
  auto it = grid_.find(core::seed_key(cell));
  if (it == grid_.end()) return;
  auto& bucket = it->second;
  bucket.erase(std::remove(bucket.begin(), bucket.end(), index), bucket.end());
  if (bucket.empty()) grid_.erase(it);
}

void TopologyGraph::set_body_radii(std::vector<double> radii_m, std::vector<double> half_widths_m) {
  half_widths_ = std::move(half_widths_m);
  if (radii_m == radii_) return;
  radii_ = std::move(radii_m);
  changed();
}

bool TopologyGraph::room_to_stand(uint64_t key, int species_index) const {
  const int i = index_of(key);
  if (i < 0 || species_index < 0 || size_t(species_index) >= half_widths_.size()) return true;
  return vertices_[i].clearance >= half_widths_[size_t(species_index)];
}

void TopologyGraph::set_clearance(uint64_t key, double clearance_m, std::vector<Eigen::Vector3d> waypoints) {
  const int i = index_of(key);
  if (i < 0) return;
  Vertex& v = vertices_[i];
  if (v.clearance == clearance_m && v.waypoints == waypoints) return;
  // Only the clearance enters path costs; a moved waypoint alone keeps cached searches.
  const bool costs_change = v.clearance != clearance_m && !radii_.empty();
  v.clearance = clearance_m;
  v.waypoints = std::move(waypoints);
  if (costs_change) changed();
}

double TopologyGraph::clearance(uint64_t key) const {
  const int i = index_of(key);
  return i < 0 ? std::numeric_limits<double>::infinity() : vertices_[i].clearance;
}

std::optional<Eigen::Vector3d> TopologyGraph::waypoint(uint64_t key, int species_index) const {
  const int i = index_of(key);
  if (i < 0) return std::nullopt;
  const Vertex& v = vertices_[i];
  if (species_index >= 0 && size_t(species_index) < v.waypoints.size()) return v.waypoints[size_t(species_index)];
  return v.position;
}

double TopologyGraph::penalty(const Vertex& v, int species_index) const {
  if (species_index < 0 || size_t(species_index) >= radii_.size()) return 0.0;
  const double r = radii_[size_t(species_index)];
  if (r <= 0.0 || v.clearance >= r) return 0.0;
  return kClearancePenaltyM * (1.0 - std::max(0.0, v.clearance) / r);
}

double TopologyGraph::clearance_penalty(uint64_t key, int species_index) const {
  const int i = index_of(key);
  return i < 0 ? 0.0 : penalty(vertices_[i], species_index);
}

void TopologyGraph::upsert_vertex(uint64_t key, const Eigen::Vector3d& position, int requirement) {
  if (requirement < 1) {
    throw std::invalid_argument("TopologyGraph::upsert_vertex: vertex " + std::to_string(key) +
                                " has traversal requirement " + std::to_string(requirement) + " (< 1)");
  }
  int i = index_of(key);
  if (i >= 0) {
    Vertex& v = vertices_[i];
    if (v.position == position && v.requirement == requirement) return;
    grid_erase(i);
    v.position = position;
    v.requirement = requirement;
    grid_insert(i);
    changed();
    return;
  }
  if (!free_.empty()) {
    i = free_.back();
    free_.pop_back();
  } else {
    i = static_cast<int>(vertices_.size());
    vertices_.emplace_back();
  }
  Vertex& v = vertices_[i];
  v.key = key;
  v.position = position;
  v.requirement = requirement;
  v.alive = true;
  v.clearance = std::numeric_limits<double>::infinity();
  v.waypoints.clear();
  v.adjacent.clear();
  index_[key] = i;
  grid_insert(i);
  changed();
}

void TopologyGraph::remove_vertex(uint64_t key) {
  const int i = index_of(key);
  if (i < 0) return;
  Vertex& v = vertices_[i];
  for (const auto& [j, len] : v.adjacent) {
    auto& adj = vertices_[j].adjacent;
    adj.erase(std::remove_if(adj.begin(), adj.end(), [&](const auto& e) { return e.first == i; }), adj.end());
    --edge_count_;
  }
  v.adjacent.clear();
  grid_erase(i);
  v.alive = false;
  index_.erase(key);
  free_.push_back(i);
  changed();
}

bool TopologyGraph::upsert_edge(uint64_t a, uint64_t b, double length_m) {
  const int i = index_of(a);
  const int j = index_of(b);
  if (i < 0 || j < 0 || i == j) return false;
  auto set_length = [&](int from, int to) -> bool {  // returns true when it existed
    for (auto& e : vertices_[from].adjacent) {
      if (e.first == to) {
        e.second = length_m;
        return true;
      }
    }
    vertices_[from].adjacent.emplace_back(to, length_m);
    return false;
  };
  // Skip the cache flush when nothing changes (edge lengths are re-sent every update).
  for (const auto& e : vertices_[i].adjacent) {
    if (e.first == j && e.second == length_m) return true;
  }
  const bool existed = set_length(i, j);
  set_length(j, i);
  if (!existed) ++edge_count_;
  changed();
  return true;
}

void TopologyGraph::remove_edge(uint64_t a, uint64_t b) {
  const int i = index_of(a);
  const int j = index_of(b);
  if (i < 0 || j < 0) return;
  auto erase = [&](int from, int to) {
    auto& adj = vertices_[from].adjacent;
    const auto before = adj.size();
    adj.erase(std::remove_if(adj.begin(), adj.end(), [&](const auto& e) { return e.first == to; }), adj.end());
    return adj.size() != before;
  };
  if (erase(i, j)) {
    erase(j, i);
    --edge_count_;
    changed();
  }
}

void TopologyGraph::clear() {
  vertices_.clear();
  free_.clear();
  index_.clear();
  grid_.clear();
  edge_count_ = 0;
  changed();
}

std::optional<Eigen::Vector3d> TopologyGraph::position(uint64_t key) const {
  const int i = index_of(key);
  if (i < 0) return std::nullopt;
  return vertices_[i].position;
}

std::optional<int> TopologyGraph::traversal_requirement(uint64_t key) const {
  const int i = index_of(key);
  if (i < 0) return std::nullopt;
  return vertices_[i].requirement;
}

bool TopologyGraph::passable(uint64_t key, int species_index) const {
  if (species_index < 0 || species_index >= species_count()) return false;
  const int i = index_of(key);
  return i >= 0 && vertices_[i].requirement <= levels_[species_index];
}

std::vector<std::pair<uint64_t, double>> TopologyGraph::neighbours(uint64_t key) const {
  std::vector<std::pair<uint64_t, double>> out;
  const int i = index_of(key);
  if (i < 0) return out;
  for (const auto& [j, len] : vertices_[i].adjacent) out.emplace_back(vertices_[j].key, len);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<uint64_t> TopologyGraph::vertex_keys() const {
  std::vector<uint64_t> keys;
  keys.reserve(index_.size());
  for (const auto& [key, i] : index_) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::shared_ptr<const TopologyGraph::Search> TopologyGraph::search(int source, int species) const {
  const uint64_t ck = cache_key(source, species);
  {
    std::lock_guard lock(cache_.mutex);
    auto it = cache_.searches.find(ck);
    if (it != cache_.searches.end()) return it->second;
  }
  const int level = levels_[species];
  auto result = std::make_shared<Search>();
  result->distance.assign(vertices_.size(), kUnreachable);
  result->predecessor.assign(vertices_.size(), -1);
  auto& dist = result->distance;
  auto& pred = result->predecessor;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[source] = 0.0;
  open.emplace(0.0, source);
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    for (const auto& [v, len] : vertices_[u].adjacent) {
      if (vertices_[v].requirement > level) continue;
      const double nd = d + len + penalty(vertices_[v], species);
      // Ties resolved towards the smaller predecessor key so paths do not depend on
      // insertion history.
      if (nd < dist[v] || (nd == dist[v] && pred[v] >= 0 && vertices_[u].key < vertices_[pred[v]].key)) {
        const bool improved = nd < dist[v];
        dist[v] = nd;
        pred[v] = u;
        if (improved) open.emplace(nd, v);
      }
    }
  }
  std::lock_guard lock(cache_.mutex);
  if (cache_.searches.size() >= max_cached_sources_) {
    cache_.searches.clear();
    cache_.bytes = 0;
  }
  auto [it, inserted] = cache_.searches.emplace(ck, std::move(result));
  if (inserted) cache_.bytes += vertices_.size() * (sizeof(double) + sizeof(int));
  return it->second;
}

double TopologyGraph::dist(uint64_t a, uint64_t b, int species_index) const {
  if (!passable(a, species_index) || !passable(b, species_index)) return kUnreachable;
  if (a == b) return 0.0;
  const auto s = search(index_of(a), species_index);
  return s->distance[index_of(b)];
}

std::vector<uint64_t> TopologyGraph::path(uint64_t a, uint64_t b, int species_index) const {
  std::vector<uint64_t> out;
  if (!passable(a, species_index) || !passable(b, species_index)) return out;
  if (a == b) return {a};
  const int source = index_of(a);
  const auto s = search(source, species_index);
  int at = index_of(b);
  if (s->distance[at] == kUnreachable) return out;
  while (at != -1) {
    out.push_back(vertices_[at].key);
    if (at == source) break;
    at = s->predecessor[at];
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::unordered_map<uint64_t, double> TopologyGraph::distances_from(uint64_t a, int species_index) const {
  std::unordered_map<uint64_t, double> out;
  if (!passable(a, species_index)) return out;
  const auto s = search(index_of(a), species_index);
  for (size_t i = 0; i < vertices_.size(); ++i) {
    if (vertices_[i].alive && s->distance[i] != kUnreachable) out.emplace(vertices_[i].key, s->distance[i]);
  }
  return out;
}

std::vector<double> TopologyGraph::distances_to(uint64_t a, const std::vector<uint64_t>& targets,
                                                int species_index) const {
  std::vector<double> out(targets.size(), kUnreachable);
  if (!passable(a, species_index)) return out;
  const int source = index_of(a);
  // Target vertex -> its positions in `targets` (passable ones only; the rest stay unreachable).
  std::unordered_map<int, std::vector<size_t>> wanted;
  for (size_t i = 0; i < targets.size(); ++i)
    if (passable(targets[i], species_index)) wanted[index_of(targets[i])].push_back(i);
  {
    std::lock_guard lock(cache_.mutex);
    if (auto it = cache_.searches.find(cache_key(source, species_index)); it != cache_.searches.end()) {
      for (const auto& [v, at] : wanted)
        for (size_t i : at) out[i] = it->second->distance[size_t(v)];
      return out;
    }
  }
  // Dijkstra as in search(), with the same edge costs, until every wanted vertex is settled.
  const int level = levels_[species_index];
  std::unordered_map<int, double> dist;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[source] = 0.0;
  open.emplace(0.0, source);
  size_t left = wanted.size();
  while (!open.empty() && left > 0) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    if (const auto w = wanted.find(u); w != wanted.end()) {
      for (size_t i : w->second) out[i] = d;
      --left;
    }
    for (const auto& [v, len] : vertices_[u].adjacent) {
      if (vertices_[v].requirement > level) continue;
      const double nd = d + len + penalty(vertices_[v], species_index);
      const auto it = dist.find(v);
      if (it == dist.end() || nd < it->second) {
        dist[v] = nd;
        open.emplace(nd, v);
      }
    }
  }
  return out;
}

std::optional<uint64_t> TopologyGraph::nearest(const Eigen::Vector3d& p) const { return nearest_impl(p, -1); }

std::optional<uint64_t> TopologyGraph::nearest(const Eigen::Vector3d& p, int species_index) const {
  if (species_index < 0 || species_index >= species_count()) return std::nullopt;
  return nearest_impl(p, species_index);
}

std::optional<uint64_t> TopologyGraph::nearest_impl(const Eigen::Vector3d& p, int species) const {
  if (index_.empty()) return std::nullopt;
  const int level = species < 0 ? std::numeric_limits<int>::max() : levels_[species];
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  auto consider = [&](int i) {
    const Vertex& v = vertices_[i];
    if (v.requirement > level) return;
    const double d2 = (v.position - p).squaredNorm();
    if (d2 < best_d2 || (d2 == best_d2 && v.key < vertices_[best].key)) {
      best_d2 = d2;
      best = i;
    }
  };
  // Expanding shells of grid cells; a shell at Chebyshev radius r holds nothing closer than
  // (r - 1) cells, so the search stops once the best hit is nearer than that.
  constexpr int kMaxShell = 12;
  const core::GridCell c = core::cell_of(p, grid_cell_m_);
  for (int r = 0; r <= kMaxShell; ++r) {
    if (best >= 0 && std::sqrt(best_d2) < (r - 1) * grid_cell_m_) return vertices_[best].key;
    for (int dz = -r; dz <= r; ++dz) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
          auto it = grid_.find(core::seed_key({c.x + dx, c.y + dy, c.z + dz}));
          if (it == grid_.end()) continue;
          for (int i : it->second) consider(i);
        }
      }
    }
  }
  if (best >= 0 && std::sqrt(best_d2) < kMaxShell * grid_cell_m_) return vertices_[best].key;
  // Far from everything: scan all vertices.
  for (const auto& [key, i] : index_) consider(i);
  if (best < 0) return std::nullopt;
  return vertices_[best].key;
}

size_t TopologyGraph::cache_bytes() const {
  std::lock_guard lock(cache_.mutex);
  return cache_.bytes;
}

size_t TopologyGraph::cached_sources() const {
  std::lock_guard lock(cache_.mutex);
  return cache_.searches.size();
}

}  // namespace hexplore::highlevel
