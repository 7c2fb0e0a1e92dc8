#include "common/highlevel/map_fusion.h"

#include <algorithm>

#include "common/core/rng.h"
#include "common/highlevel/wire_precision.h"

namespace hexplore::highlevel {
namespace {

// Folds `value` into a running per-element hash.
uint64_t fold(uint64_t hash, uint64_t value) { return core::splitmix_finalize(hash ^ (value + 0x9E3779B97F4A7C15ull)); }

// What a supervoxel is on the wire (map_proto.cc): a receiver decodes the same values.
uint64_t wire_hash(const Supervoxel& s) {
  uint64_t h = fold(0x5eed, s.key);
  for (int i = 0; i < 3; ++i) h = fold(h, static_cast<uint64_t>(centre_steps(s.center[i])));
  const PackedNormal n = pack_normal(s.normal);
  h = fold(h, (static_cast<uint64_t>(static_cast<uint8_t>(n.u)) << 8) | static_cast<uint8_t>(n.v));
  h = fold(h, (s.covered ? 1u : 0u) | (static_cast<uint64_t>(std::max(0, s.traversal_requirement)) << 1));
  h = fold(h, static_cast<uint64_t>(s.surface));
  h = fold(h, static_cast<uint64_t>(std::max(0, s.voxel_count)));
  if (!s.covered) {  // covered ones travel without these (the receiver fills them in)
    h = fold(h, static_cast<uint64_t>(std::max(0, s.covered_voxels)));
    h = fold(h, static_cast<uint64_t>(s.gap));
  }
  return h;
}

}  // namespace

void Contribution::apply(const MapUpdate& update, std::unordered_set<uint64_t>* touched_keys,
                         std::unordered_set<EdgeKey, EdgeKeyHash>* touched_edges) {
  if (update.full_snapshot) {
    if (touched_keys != nullptr)
      for (const auto& [key, sv] : supervoxels) touched_keys->insert(key);
    if (touched_edges != nullptr)
      for (const EdgeKey& e : edges) touched_edges->insert(e);
    supervoxels.clear();
    edges.clear();
  }
  for (uint64_t key : update.removals) {
    if (supervoxels.erase(key) != 0 && touched_keys != nullptr) touched_keys->insert(key);
  }
  for (const Supervoxel& sv : update.upserts) {
    supervoxels[sv.key] = sv;
    if (touched_keys != nullptr) touched_keys->insert(sv.key);
  }
  for (const EdgeKey& raw : update.edge_removals) {
    const EdgeKey e = EdgeKey::of(raw.a, raw.b);
    if (edges.erase(e) != 0 && touched_edges != nullptr) touched_edges->insert(e);
  }
  for (const EdgeKey& raw : update.edge_upserts) {
    const EdgeKey e = EdgeKey::of(raw.a, raw.b);
    if (e.a != e.b && edges.insert(e).second && touched_edges != nullptr) touched_edges->insert(e);
  }
}

MapUpdate Contribution::snapshot() const {
  MapUpdate u;
  u.full_snapshot = true;
  u.upserts.reserve(supervoxels.size());
  for (const auto& [key, sv] : supervoxels) u.upserts.push_back(sv);
  std::sort(u.upserts.begin(), u.upserts.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  u.edge_upserts.assign(edges.begin(), edges.end());
  std::sort(u.edge_upserts.begin(), u.edge_upserts.end());
  return u;
}

uint32_t Contribution::digest() const {
  // A sum of element hashes: the containers' order does not matter.
  uint64_t sum = supervoxels.size() * 0x2545F4914F6CDD1Dull + edges.size();
  for (const auto& [key, sv] : supervoxels) sum += wire_hash(sv);
  for (const EdgeKey& e : edges) sum += fold(fold(0xed9e, e.a), e.b);
  const uint32_t folded = static_cast<uint32_t>(core::splitmix_finalize(sum) >> 32);
  return folded == 0 ? 1 : folded;  // 0 means "not given" on the wire
}

Supervoxel fuse(const std::vector<const Supervoxel*>& reports) {
  Supervoxel out = *reports.front();
  if (reports.size() == 1) return out;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  bool na = false;
  int requirement = 0;
  for (const Supervoxel* r : reports) {
    center += r->center;
    normal += r->normal;
    out.covered = out.covered || r->covered;
    out.voxel_count = std::max(out.voxel_count, r->voxel_count);
    if (r->traversal_requirement == 0) na = true;
    requirement = std::max(requirement, r->traversal_requirement);
  }
  out.center = center / static_cast<double>(reports.size());
  out.normal = normal.norm() > 0.0 ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d::UnitZ();
  out.traversal_requirement = na ? 0 : requirement;
  // Coverage is OR: complete when any source completed it. Otherwise the source that got
  // furthest (largest complete fraction; ties: the first source) tells how far and why not.
  if (out.covered) {
    out.covered_voxels = out.voxel_count;
    out.gap = core::CoverageGap::kNone;
  } else {
    const Supervoxel* best = reports.front();
    auto fraction = [](const Supervoxel* s) { return double(s->covered_voxels) / std::max(1, s->voxel_count); };
    for (const Supervoxel* r : reports)
      if (fraction(r) > fraction(best)) best = r;
    out.covered_voxels = best->covered_voxels;
    out.gap = best->gap;
  }
  return out;
}

MapFusion::MapFusion(std::vector<int> species_levels) : map_(std::move(species_levels)) {}

const Contribution* MapFusion::contribution(const std::string& source) const {
  auto it = sources_.find(source);
  return it == sources_.end() ? nullptr : &it->second;
}

std::vector<std::string> MapFusion::sources() const {
  std::vector<std::string> out;
  for (const auto& [name, c] : sources_) out.push_back(name);
  return out;
}

void MapFusion::apply(const std::string& source, const MapUpdate& change) {
  Contribution& c = sources_[source];
  // Remember which touched edges this source had, so counts move only on real transitions.
  std::unordered_map<EdgeKey, bool, EdgeKeyHash> had;
  if (change.full_snapshot)
    for (const EdgeKey& e : c.edges) had[e] = true;
  for (const auto* list : {&change.edge_removals, &change.edge_upserts})
    for (const EdgeKey& raw : *list) {
      const EdgeKey e = EdgeKey::of(raw.a, raw.b);
      had.emplace(e, c.edges.count(e) != 0);
    }
  std::unordered_set<uint64_t> keys;
  c.apply(change, &keys, nullptr);
  std::unordered_set<EdgeKey, EdgeKeyHash> edges;
  for (const auto& [e, before] : had) {
    const bool now = c.edges.count(e) != 0;
    if (now != before) {
      edge_sources_[e] += now ? 1 : -1;
      edges.insert(e);
    }
  }
  if (change.full_snapshot) {
    for (const EdgeKey& e : c.edges) {
      if (had.count(e) == 0) {
        ++edge_sources_[e];
        edges.insert(e);
      }
    }
  }
  refuse(keys, edges);
}

void MapFusion::remove_source(const std::string& source) {
  auto it = sources_.find(source);
  if (it == sources_.end()) return;
  std::unordered_set<uint64_t> keys;
  std::unordered_set<EdgeKey, EdgeKeyHash> edges;
  for (const auto& [key, sv] : it->second.supervoxels) keys.insert(key);
  for (const EdgeKey& e : it->second.edges) {
    --edge_sources_[e];
    edges.insert(e);
  }
  sources_.erase(it);
  refuse(keys, edges);
}

void MapFusion::refuse(const std::unordered_set<uint64_t>& keys,
                       const std::unordered_set<EdgeKey, EdgeKeyHash>& edges) {
  MapUpdate fused;
  std::vector<const Supervoxel*> reports;
  for (uint64_t key : keys) {
    reports.clear();
    for (const auto& [name, c] : sources_) {
      auto it = c.supervoxels.find(key);
      if (it != c.supervoxels.end()) reports.push_back(&it->second);
    }
    const Supervoxel* current = map_.find(key);
    if (reports.empty()) {
      if (current != nullptr) {
        fused.removals.push_back(key);
        pending_keys_.insert(key);
      }
      continue;
    }
    Supervoxel sv = fuse(reports);
    if (current == nullptr || !(*current == sv)) {
      fused.upserts.push_back(sv);
      pending_keys_.insert(key);
    }
  }
  for (const EdgeKey& e : edges) {
    auto it = edge_sources_.find(e);
    const bool present = it != edge_sources_.end() && it->second > 0;
    if (it != edge_sources_.end() && it->second <= 0) edge_sources_.erase(it);
    const bool in_map = map_.edges().count(e) != 0;
    if (present && !in_map) fused.edge_upserts.push_back(e);
    if (!present && in_map) fused.edge_removals.push_back(e);
    if (present != in_map) pending_edges_.insert(e);
  }
  // Sorted so that the map sees the same batch on every robot.
  std::sort(fused.upserts.begin(), fused.upserts.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  std::sort(fused.removals.begin(), fused.removals.end());
  std::sort(fused.edge_upserts.begin(), fused.edge_upserts.end());
  std::sort(fused.edge_removals.begin(), fused.edge_removals.end());
  map_.apply(fused);
}

MapUpdate MapFusion::take_changes() {
  MapUpdate u;
  u.version = map_.version();
  for (uint64_t key : pending_keys_) {
    const Supervoxel* sv = map_.find(key);
    if (sv != nullptr) {
      u.upserts.push_back(*sv);
    } else {
      u.removals.push_back(key);
    }
  }
  for (const EdgeKey& e : pending_edges_) {
    if (map_.edges().count(e) != 0) {
      u.edge_upserts.push_back(e);
    } else {
      u.edge_removals.push_back(e);
    }
  }
  pending_keys_.clear();
  pending_edges_.clear();
  return u;
}

}  // namespace hexplore::highlevel
