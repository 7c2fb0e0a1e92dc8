#pragma once
// Fusion of the team's high-level maps (paper "Incremental Transmission and Map Fusion"):
// every source robot's latest contribution is kept per key, and the fused supervoxel is
// recomputed from them — traversal requirement by maximum (N/A, the strictest, wins),
// coverage by logical OR, normal and centre by average — so the fused map depends only on
// the sources' current contributions, not on the order their increments arrived.

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "common/highlevel/high_level_map.h"

namespace hexplore::highlevel {

// One source's contribution: its supervoxels and edges as it last reported them.
struct Contribution {
  std::unordered_map<uint64_t, Supervoxel> supervoxels;
  std::unordered_set<EdgeKey, EdgeKeyHash> edges;

  // Applies an increment (or, with full_snapshot, replaces everything); returns the keys and
  // edges it touched.
  void apply(const MapUpdate& update, std::unordered_set<uint64_t>* touched_keys = nullptr,
             std::unordered_set<EdgeKey, EdgeKeyHash>* touched_edges = nullptr);
  // The whole contribution as one full-snapshot update (keys ascending).
  MapUpdate snapshot() const;
  // A 32-bit digest of what travels on the radio of this contribution (keys, centres on the
  // wire grid, packed normals, the attributes map_proto sends, edges), independent of order:
  // equal on the source and on every receiver that applied the same increments. Never 0.
  uint32_t digest() const;
};

// Fuses supervoxels reported by several sources (iterated in source-name order so that
// floating-point sums are identical on every robot).
Supervoxel fuse(const std::vector<const Supervoxel*>& reports);

class MapFusion {
 public:
  explicit MapFusion(std::vector<int> species_levels);

  // Applies a change to `source`'s contribution and updates the fused map.
  void apply(const std::string& source, const MapUpdate& change);
  // Forgets a source entirely (its keys fall back to the remaining sources).
  void remove_source(const std::string& source);

  const HighLevelMap& map() const { return map_; }
  const Contribution* contribution(const std::string& source) const;
  std::vector<std::string> sources() const;
  // Fused changes accumulated since the previous call (current values of every key and edge
  // that changed), for the FusedMapUpdate increments sent to planning.
  MapUpdate take_changes();

 private:
  void refuse(const std::unordered_set<uint64_t>& keys, const std::unordered_set<EdgeKey, EdgeKeyHash>& edges);

  std::map<std::string, Contribution> sources_;
  std::unordered_map<EdgeKey, int, EdgeKeyHash> edge_sources_;  // how many sources report it
  HighLevelMap map_;
  std::set<uint64_t> pending_keys_;
  std::set<EdgeKey> pending_edges_;
};

}  // namespace hexplore::highlevel
