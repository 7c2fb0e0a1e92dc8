#pragma once
// Memoised voxel lookups by key offset for one scan's metric updates: each key is searched in
// the octree once, then answered from a flat hash map (absent voxels included).

#include <octomap/OcTreeKey.h>

#include "common/perception/flat_key_map.h"
#include "common/perception/voxel_octree.h"

namespace hexplore::perception {

class NeighbourLookup {
 public:
  NeighbourLookup(const VoxelOcTree& tree, FlatKeyMap<VoxelNode*>& memo) : tree_(tree), memo_(memo) {}

  VoxelNode* at(const octomap::OcTreeKey& key) {
    bool inserted = false;
    VoxelNode*& slot = memo_.find_or_insert(pack_key(key), nullptr, inserted);
    if (inserted) slot = tree_.search(key);
    return slot;
  }
  // The voxel at `key` + (dx, dy, dz); keys wrap at the octree border, thousands of metres out.
  VoxelNode* at(const octomap::OcTreeKey& key, int dx, int dy, int dz) {
    return at(offset(key, dx, dy, dz));
  }
  static octomap::OcTreeKey offset(const octomap::OcTreeKey& key, int dx, int dy, int dz) {
    return octomap::OcTreeKey(static_cast<octomap::key_type>(key[0] + dx), static_cast<octomap::key_type>(key[1] + dy),
                              static_cast<octomap::key_type>(key[2] + dz));
  }

 private:
  const VoxelOcTree& tree_;
  FlatKeyMap<VoxelNode*>& memo_;
};

}  // namespace hexplore::perception
