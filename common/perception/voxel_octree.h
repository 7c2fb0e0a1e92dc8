#pragma once
// The perception map's octree: octomap's OcTreeBaseImpl over a custom node type whose value
// is a VoxelData (like octomap's ColorOcTree/CountingOcTree). Leaves at full depth are the
// occupied voxels; inner nodes only route. Nodes are never pruned, so node pointers stay
// valid until the tree is cleared.

#include <cstdint>
#include <string>

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTreeBaseImpl.h>
#include <octomap/OcTreeDataNode.h>

#include "common/core/seed_key.h"
#include "common/perception/voxel_data.h"

namespace hexplore::perception {

class VoxelNode : public octomap::OcTreeDataNode<VoxelData> {
 public:
  VoxelNode() : octomap::OcTreeDataNode<VoxelData>(VoxelData{}) {}
  VoxelData& data() { return value; }
  const VoxelData& data() const { return value; }
};

class VoxelOcTree : public octomap::OcTreeBaseImpl<VoxelNode, octomap::AbstractOcTree> {
 public:
  explicit VoxelOcTree(double resolution);

  VoxelOcTree* create() const override { return new VoxelOcTree(resolution); }
  std::string getTreeType() const override { return "HexploreVoxelOcTree"; }

  // The leaf at `key` (full depth), created with empty data when absent.
  VoxelNode* find_or_create(const octomap::OcTreeKey& key, bool& created);
};

// A voxel's integer grid index is a core::GridCell: centre = (x + 0.5) * resolution (the
// hexplore.v1.Voxel keys; the high-level map's voxel samples use the same type).

inline constexpr int32_t kOctreeKeyOffset = 32768;  // octomap's tree_max_val at depth 16

inline core::GridCell to_voxel_key(const octomap::OcTreeKey& k) {
  return {static_cast<int32_t>(k[0]) - kOctreeKeyOffset, static_cast<int32_t>(k[1]) - kOctreeKeyOffset,
          static_cast<int32_t>(k[2]) - kOctreeKeyOffset};
}
// False when the index lies outside the octree's range.
inline bool to_octree_key(const core::GridCell& v, octomap::OcTreeKey& out) {
  const int32_t c[3] = {v.x + kOctreeKeyOffset, v.y + kOctreeKeyOffset, v.z + kOctreeKeyOffset};
  for (int i = 0; i < 3; ++i) {
    if (c[i] < 0 || c[i] > 0xFFFF) return false;
    out[i] = static_cast<octomap::key_type>(c[i]);
  }
  return true;
}
inline uint64_t pack_key(const octomap::OcTreeKey& k) {
  return static_cast<uint64_t>(k[0]) | (static_cast<uint64_t>(k[1]) << 16) | (static_cast<uint64_t>(k[2]) << 32);
}

}  // namespace hexplore::perception
