#include "common/highlevel/high_level_map.h"

#include <algorithm>

#include "common/highlevel/slopes.h"

namespace hexplore::highlevel {

HighLevelMap::HighLevelMap(std::vector<int> species_levels, ClearanceOptions clearance)
    : levels_(species_levels), graph_(std::move(species_levels)), clearance_(std::move(clearance)) {
  graph_.set_body_radii(clearance_.options().body_radius_m, clearance_.options().body_half_width_m);
}

void HighLevelMap::clear() {
  supervoxels_.clear();
  edges_.clear();
  incident_.clear();
  graph_.clear();
  clearance_.clear();
  frontier_sides_.clear();
  bridged_.clear();
}

void HighLevelMap::sync_clearance(uint64_t key) {
  const Supervoxel* sv = find(key);
  if (sv == nullptr || !graph_.contains(key)) {
    frontier_sides_.erase(key);
    return;
  }
  ClearanceIndex::Measure m = clearance_.measure(*sv, clearance_.search_m(), clearance_.options().body_radius_m);
  graph_.set_clearance(key, m.clearance, std::move(m.waypoints));
  const ClearanceIndex::RimSides rim = clearance_.rim_sides(*sv);
  const uint8_t sides = rim.open | uphill_sides(*sv, rim.walled);
  if (sides != 0) frontier_sides_[key] = sides;
  else frontier_sides_.erase(key);
}

double HighLevelMap::bridge_reach_m() const { return 1.75 * clearance_.options().ground_spacing_m; }

void HighLevelMap::unbridge(uint64_t a, uint64_t b) {
  for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
    auto it = bridged_.find(x);
    if (it == bridged_.end()) continue;
    auto& v = it->second;
    v.erase(std::remove(v.begin(), v.end(), y), v.end());
    if (v.empty()) bridged_.erase(it);
  }
  if (edges_.count(EdgeKey::of(a, b)) == 0) graph_.remove_edge(a, b);
}

void HighLevelMap::drop_bridges(uint64_t key) {
  const auto it = bridged_.find(key);
  if (it == bridged_.end()) return;
  const std::vector<uint64_t> old = it->second;
  for (uint64_t other : old) unbridge(key, other);
}

void HighLevelMap::sync_bridges(uint64_t key) {
  drop_bridges(key);
  const Supervoxel* sv = find(key);
  if (sv == nullptr || !graph_.contains(key) || !sloped(*sv)) return;
  for (uint64_t other : clearance_.ground_near(sv->center, bridge_reach_m())) {
    const Supervoxel* o = find(other);
    if (other == key || o == nullptr || !graph_.contains(other) || !on_one_slope(*sv, *o, bridge_reach_m())) continue;
    bridged_[key].push_back(other);
    bridged_[other].push_back(key);
    graph_.upsert_edge(key, other, (sv->center - o->center).norm());
  }
}

bool HighLevelMap::bridged(uint64_t a, uint64_t b) const {
  const auto it = bridged_.find(a);
  return it != bridged_.end() && std::find(it->second.begin(), it->second.end(), b) != it->second.end();
}

uint8_t HighLevelMap::frontier_sides(uint64_t key) const {
  const auto it = frontier_sides_.find(key);
  return it == frontier_sides_.end() ? 0 : it->second;
}

const Supervoxel* HighLevelMap::find(uint64_t key) const {
  auto it = supervoxels_.find(key);
  return it == supervoxels_.end() ? nullptr : &it->second;
}

// Makes the graph vertex of `key` match its supervoxel, then its incident edges.
void HighLevelMap::sync_vertex(uint64_t key) {
  const Supervoxel* sv = find(key);
  if (sv == nullptr || !sv->traversable()) {
    graph_.remove_vertex(key);
    return;
  }
  graph_.upsert_vertex(key, sv->center, sv->traversal_requirement);
  auto it = incident_.find(key);
  if (it == incident_.end()) return;
  for (uint64_t other : it->second) sync_edge(EdgeKey::of(key, other));
}

void HighLevelMap::sync_edge(const EdgeKey& e) {
  const Supervoxel* a = find(e.a);
  const Supervoxel* b = find(e.b);
  if (edges_.count(e) == 0 || a == nullptr || b == nullptr || !a->traversable() || !b->traversable()) {
    if (!bridged(e.a, e.b)) graph_.remove_edge(e.a, e.b);
    return;
  }
  graph_.upsert_edge(e.a, e.b, (a->center - b->center).norm());
}

void HighLevelMap::apply(const MapUpdate& update) {
  if (update.empty()) return;
  if (update.full_snapshot) clear();
  // Clearance bookkeeping: ground whose own supervoxel changed, and ground near a facade that
  // appeared, moved or went, or near ground that did (the rim of the known ground moves).
  const bool clearance = clearance_.options().enabled();
  std::vector<uint64_t> dirty;
  std::vector<Eigen::Vector3d> touched;
  auto forget = [&](uint64_t key) {
    const Supervoxel* old = find(key);
    if (!clearance || old == nullptr) return;
    clearance_.erase(*old);
    touched.push_back(old->center);
  };
  for (uint64_t key : update.removals) {
    forget(key);
    supervoxels_.erase(key);
    graph_.remove_vertex(key);
    drop_bridges(key);
    frontier_sides_.erase(key);
  }
  for (const EdgeKey& e : update.edge_removals) {
    if (edges_.erase(e) == 0) continue;
    for (auto [x, y] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
      auto it = incident_.find(x);
      if (it == incident_.end()) continue;
      auto& v = it->second;
      v.erase(std::remove(v.begin(), v.end(), y), v.end());
      if (v.empty()) incident_.erase(it);
    }
    if (!bridged(e.a, e.b)) graph_.remove_edge(e.a, e.b);
  }
  for (const Supervoxel& sv : update.upserts) {
    const Supervoxel* old = find(sv.key);
    // Clearance depends only on where supervoxels are, which way they face and, for ground,
    // which species may stand there (a ceiling is over some bodies only) and whether ground is a
    // one-voxel sliver (which closes no side).
    const bool moved = old == nullptr || old->center != sv.center || old->normal != sv.normal || old->surface != sv.surface ||
                       old->traversal_requirement != sv.traversal_requirement ||
                       sliver_of_ground(*old) != sliver_of_ground(sv);
    if (moved) forget(sv.key);
    supervoxels_[sv.key] = sv;
    if (!clearance) continue;
    if (moved) {
      clearance_.insert(sv);
      touched.push_back(sv.center);
    }
    if (sv.ground()) dirty.push_back(sv.key);
  }
  for (const EdgeKey& e : update.edge_upserts) {
    if (e.a == e.b || !edges_.insert(EdgeKey::of(e.a, e.b)).second) continue;
    incident_[e.a].push_back(e.b);
    incident_[e.b].push_back(e.a);
  }
  // Vertices first (an edge needs both ends), then every edge touching a changed vertex.
  for (const Supervoxel& sv : update.upserts) sync_vertex(sv.key);
  for (const EdgeKey& e : update.edge_upserts) sync_edge(EdgeKey::of(e.a, e.b));
  if (clearance) {
    const double reach = clearance_.influence_m();
    for (const auto& p : touched)
      for (uint64_t key : clearance_.ground_near(p, reach)) dirty.push_back(key);
    std::sort(dirty.begin(), dirty.end());
    dirty.erase(std::unique(dirty.begin(), dirty.end()), dirty.end());
    for (uint64_t key : dirty) sync_bridges(key);  // before clearance: a bridge joins the graph
    for (uint64_t key : dirty) sync_clearance(key);
  }
  ++version_;
}

MapUpdate HighLevelMap::snapshot() const {
  MapUpdate u;
  u.full_snapshot = true;
  u.version = version_;
  u.upserts.reserve(supervoxels_.size());
  for (const auto& [key, sv] : supervoxels_) u.upserts.push_back(sv);
  u.edge_upserts.assign(edges_.begin(), edges_.end());
  return u;
}

bool same_map(const HighLevelMap& a, const HighLevelMap& b) {
  return a.supervoxels() == b.supervoxels() && a.edges() == b.edges();
}

}  // namespace hexplore::highlevel
