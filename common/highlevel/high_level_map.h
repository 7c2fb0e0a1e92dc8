#pragma once
// The fused high-level map a robot plans on: supervoxels by key (iterated in key order, the
// same on every robot) plus the traversal-topology graph over the ground ones. It is fed by
// MapUpdate batches: fused changes from MapFusion inside hlmap, or FusedMapUpdate messages
// received by planning (see map_proto.h). With clearance options (planning's map), every
// graph vertex also carries its clearance from the facades around it and, per species, a
// waypoint moved away from them (see clearance.h, topology_graph.h), and the sides on which
// the known ground ends (its rim: the frontier of what the team has seen of the ground).

#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>
#include <vector>

#include "common/highlevel/clearance.h"
#include "common/highlevel/supervoxel.h"
#include "common/highlevel/topology_graph.h"

namespace hexplore::highlevel {

// A batch of changes to a map: new or changed supervoxels, removed keys, added and removed
// edges. A full snapshot replaces the whole map.
struct MapUpdate {
  bool full_snapshot = false;
  uint64_t version = 0;  // FusedMapUpdate.version when it came from the wire
  std::vector<Supervoxel> upserts;
  std::vector<uint64_t> removals;
  std::vector<EdgeKey> edge_upserts;
  std::vector<EdgeKey> edge_removals;
  // Supervoxels of the wire message left out as malformed (map_proto.h); not part of the change.
  size_t malformed = 0;

  bool empty() const {
    return !full_snapshot && upserts.empty() && removals.empty() && edge_upserts.empty() &&
           edge_removals.empty();
  }
};

class HighLevelMap {
 public:
  // levels[k] = traversal capability level of species index k (species_levels(team)).
  explicit HighLevelMap(std::vector<int> species_levels = {1}, ClearanceOptions clearance = {});

  // Applies a batch. Edge lengths are always the distance between the current supervoxel
  // centres; edges whose endpoints are not both traversable ground stay in the edge set but
  // are not in the graph until they are.
  void apply(const MapUpdate& update);
  void clear();

  const Supervoxel* find(uint64_t key) const;
  // Supervoxels in ascending key order.
  const std::map<uint64_t, Supervoxel>& supervoxels() const { return supervoxels_; }
  // Edges (a < b) in ascending order.
  const std::set<EdgeKey>& edges() const { return edges_; }
  const TopologyGraph& graph() const { return graph_; }
  size_t size() const { return supervoxels_.size(); }
  // The whole map as one full-snapshot update.
  MapUpdate snapshot() const;
  // Planning's map (with clearance options): the sides of ground vertex `key` where the known
  // ground ends (bit i: rim_side_direction(i)): its rim (ClearanceIndex::rim_sides), and on a
  // slope, an uphill side where a wall stands and no ground is seen beyond (the next step of a
  // flight seen from its foot). 0 for anything else, and always 0 without clearance options.
  uint8_t frontier_sides(uint64_t key) const;
  const ClearanceOptions& clearance_options() const { return clearance_.options(); }
  // Number of applied batches that changed something.
  uint64_t version() const { return version_; }

 private:
  void sync_vertex(uint64_t key);
  void sync_edge(const EdgeKey& e);
  void sync_clearance(uint64_t key);
  // Slope bridges (slopes.h): edges of the graph between ground pieces on one slope that the
  // map's own edges do not join (a riser between them). Kept beside the shared edges, so a
  // shared edge that goes leaves a bridge in place and a bridge that goes leaves a shared edge.
  double bridge_reach_m() const;
  void sync_bridges(uint64_t key);
  void drop_bridges(uint64_t key);
  void unbridge(uint64_t a, uint64_t b);
  bool bridged(uint64_t a, uint64_t b) const;

  std::vector<int> levels_;
  std::map<uint64_t, Supervoxel> supervoxels_;
  std::set<EdgeKey> edges_;
  std::unordered_map<uint64_t, std::vector<uint64_t>> incident_;  // key -> edge partners
  TopologyGraph graph_;
  ClearanceIndex clearance_;
  std::unordered_map<uint64_t, uint8_t> frontier_sides_;  // ground vertices with a frontier side only
  std::unordered_map<uint64_t, std::vector<uint64_t>> bridged_;  // key -> slope-bridge partners
  uint64_t version_ = 0;
};

// True when two maps hold the same supervoxels (keys and attributes) and edges.
bool same_map(const HighLevelMap& a, const HighLevelMap& b);

}  // namespace hexplore::highlevel
