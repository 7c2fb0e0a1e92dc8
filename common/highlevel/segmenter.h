#pragma once
// Improved supervoxel segmentation of the perception map (paper "Supervoxel Segmentation"):
// one seed per eta_s grid cell and surface class (ground, or facade of one facing), BFS merging of adjacent seeds closer than
// eta_e (keeps a noisy, thick ground slab in one layer), and region growth by wavefront
// propagation over the voxel hash (26-neighbourhood lookups, no KD-tree). Updates are
// incremental: only the cells touched by a voxel delta (and a one-cell margin) are re-grown,
// and supervoxel attributes are kept as exact integer sums, so the result depends only on the
// current voxel set, never on the order in which deltas arrived.

#include <cstdint>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "common/highlevel/segmenter_params.h"
#include "common/highlevel/supervoxel.h"
#include "common/highlevel/supervoxel_stats.h"
#include "common/highlevel/voxel_index.h"
#include "common/highlevel/voxel_sample.h"

namespace hexplore::highlevel {

// What one update changed in the segmenter's supervoxel map.
struct SegmentationChange {
  std::vector<uint64_t> upserted;  // new or changed supervoxels (keys, ascending)
  std::vector<uint64_t> removed;   // supervoxels that no longer exist
  std::vector<EdgeKey> edges_added;
  std::vector<EdgeKey> edges_removed;
  size_t relabelled_voxels = 0;    // voxels whose label was re-derived (work done)
  bool empty() const {
    return upserted.empty() && removed.empty() && edges_added.empty() && edges_removed.empty();
  }
};

class SupervoxelSegmenter {
 public:
  // levels[k] = traversal capability level of species index k (species_levels(team)).
  SupervoxelSegmenter(SegmenterParams params, std::vector<int> species_levels);

  // Applies voxel samples (new, changed or removed voxels) and re-segments what they touch.
  SegmentationChange update(std::span<const VoxelSample> voxels);
  // Makes `voxels` the whole voxel set (a full-snapshot VoxelDelta): voxels not in it are
  // removed, in the same single incremental update.
  SegmentationChange replace_all(std::span<const VoxelSample> voxels);

  const std::unordered_map<uint64_t, Supervoxel>& supervoxels() const { return supervoxels_; }
  const Supervoxel* find(uint64_t key) const;
  // Topology edges between adjacent ground supervoxels (a < b), ascending.
  std::vector<EdgeKey> edges() const;
  size_t edge_count() const { return edge_count_; }
  size_t voxel_count() const { return voxels_.size(); }
  // Supervoxel key a voxel belongs to; 0 when the voxel is unknown.
  uint64_t supervoxel_of(const core::GridCell& voxel) const;
  const SegmenterParams& params() const { return params_; }

 private:
  struct VoxelRec {
    VoxelSample sample;
    uint64_t seed_cell = 0;  // class-tagged key of the eta_s cell holding the voxel
    uint64_t label = 0;      // class-tagged key of the seed whose region holds the voxel
    uint64_t cls = 0;         // class bits of its supervoxel keys: 0 = ground, else facade + facing
    // Wavefront state, valid when the stamps equal the current propagation's stamp.
    uint32_t visit_stamp = 0;
    uint32_t candidate_stamp = 0;
    uint64_t wave_label = 0;
    uint64_t candidate_label = 0;
  };
  struct Seed {  // one eta_s cell of one class
    std::unordered_set<uint64_t> cell_voxels;  // voxels inside the cell
    int64_t key_sum[3] = {0, 0, 0};            // for the centroid of the cell's voxels
    uint64_t seed_voxel = 0;                   // voxel nearest the centroid: wavefront source
    std::unordered_set<uint64_t> region;       // voxels labelled with this seed
    VoxelSetStats stats;                       // over `region`
  };

  uint64_t voxel_key(const core::GridCell& c) const { return core::seed_key(c); }
  uint64_t seed_cell_of_voxel(const core::GridCell& c, uint64_t cls) const;
  Eigen::Vector3d voxel_center(uint64_t vkey) const;
  Eigen::Vector3d centroid(const Seed& s) const;
  void remove_voxel(uint64_t vkey, std::unordered_set<uint64_t>& dirty_seeds);
  void insert_voxel(const VoxelSample& v, std::unordered_set<uint64_t>& dirty_seeds);
  std::unordered_set<uint64_t> refresh_seeds(const std::unordered_set<uint64_t>& dirty_seeds);
  void regroup(const std::unordered_set<uint64_t>& changed_seeds);
  size_t relabel(const std::unordered_set<uint64_t>& dirty_seeds);  // returns voxels examined
  void set_label(uint64_t vkey, VoxelRec& rec, uint64_t label);
  Supervoxel aggregate(uint64_t group) const;
  // Whether the group holds a connected patch of at least min_ise_patch_voxels incomplete voxels.
  bool has_ise_patch(uint64_t group) const;
  std::unordered_set<uint64_t> ground_neighbours(uint64_t group) const;
  uint64_t group_of_seed(uint64_t seed) const;

  SegmenterParams params_;
  std::vector<int> levels_;
  int hops_ = 5;
  VoxelIndex<VoxelRec> voxels_;
  uint32_t stamp_ = 0;
  std::unordered_map<uint64_t, Seed> seeds_;
  std::unordered_map<uint64_t, uint64_t> seed_group_;                // seed -> group key
  std::unordered_map<uint64_t, std::vector<uint64_t>> groups_;       // group key -> seeds
  std::unordered_map<uint64_t, Supervoxel> supervoxels_;             // group key -> attributes
  std::unordered_map<uint64_t, std::unordered_set<uint64_t>> adjacency_;  // ground groups
  size_t edge_count_ = 0;

  // Per-update bookkeeping.
  std::unordered_set<uint64_t> touched_groups_;    // attributes may have changed
  std::unordered_set<uint64_t> reshaped_groups_;   // voxel membership changed: redo edges
  std::unordered_set<uint64_t> dissolved_groups_;  // group keys that existed before regroup
  std::unordered_set<uint64_t> touched_seeds_;     // seeds whose region or stats changed
};

}  // namespace hexplore::highlevel
