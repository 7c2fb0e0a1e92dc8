#pragma once
// Memoised voxel lookups by key offset for one scan's metric updates. Voxels are fetched a
// 4x4x4 brick at a time: one octree descent to the brick's node two levels above the leaves,
// then its 64 leaf pointers are read from the children. Neighbourhood queries then mostly hit
// a brick already fetched, instead of repeating a 16-level descent per neighbour.

#include <array>
#include <cstdint>
#include <vector>

#include <octomap/OcTreeKey.h>

#include "common/perception/flat_key_map.h"
#include "common/perception/voxel_octree.h"

namespace hexplore::perception {

class NeighbourLookup {
 public:
  using Brick = std::array<VoxelNode*, 64>;

  // `bricks` and `index` are scan-local storage owned by the caller (kept for their capacity).
  NeighbourLookup(const VoxelOcTree& tree, std::vector<Brick>& bricks, FlatKeyMap<uint32_t>& index)
      : tree_(tree), bricks_(bricks), index_(index) {}

  VoxelNode* at(const octomap::OcTreeKey& key) {
    const uint64_t brick_key = pack_key(octomap::OcTreeKey(key[0] >> 2, key[1] >> 2, key[2] >> 2));
    if (brick_key != last_key_) {
      const uint32_t slot = slot_of(key);
      last_key_ = brick_key;
      last_ = &bricks_[slot];
    }
    return (*last_)[(key[0] & 3) | ((key[1] & 3) << 2) | ((key[2] & 3) << 4)];
  }
  // The 3x3x3 block around `key`: out[(dz+1)*9 + (dy+1)*3 + (dx+1)], nullptr where empty.
  // Resolves the at most eight bricks the block spans once, instead of once per cell.
  void gather27(const octomap::OcTreeKey& key, VoxelNode* out[27]) {
    octomap::key_type lo[3];
    unsigned span[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = static_cast<octomap::key_type>(key[a] - 1);
      const octomap::key_type hi = static_cast<octomap::key_type>(key[a] + 1);
      span[a] = (hi >> 2) != (lo[a] >> 2) ? 2 : 1;
    }
    uint32_t slots[8];
    for (unsigned bz = 0; bz < span[2]; ++bz)
      for (unsigned by = 0; by < span[1]; ++by)
        for (unsigned bx = 0; bx < span[0]; ++bx) {
          const octomap::OcTreeKey corner(static_cast<octomap::key_type>(lo[0] + bx * 4),
                                          static_cast<octomap::key_type>(lo[1] + by * 4),
                                          static_cast<octomap::key_type>(lo[2] + bz * 4));
          slots[bx | (by << 1) | (bz << 2)] = slot_of(corner);
        }
    for (int dz = 0; dz < 3; ++dz)
      for (int dy = 0; dy < 3; ++dy)
        for (int dx = 0; dx < 3; ++dx) {
          const octomap::key_type x = static_cast<octomap::key_type>(lo[0] + dx);
          const octomap::key_type y = static_cast<octomap::key_type>(lo[1] + dy);
          const octomap::key_type z = static_cast<octomap::key_type>(lo[2] + dz);
          const unsigned b = (((x >> 2) != (lo[0] >> 2)) ? 1u : 0u) | (((y >> 2) != (lo[1] >> 2)) ? 2u : 0u) |
                             (((z >> 2) != (lo[2] >> 2)) ? 4u : 0u);
          out[dz * 9 + dy * 3 + dx] = bricks_[slots[b]][(x & 3) | ((y & 3) << 2) | ((z & 3) << 4)];
        }
  }

  // The voxel at `key` + (dx, dy, dz); keys wrap at the octree border, thousands of metres out.
  VoxelNode* at(const octomap::OcTreeKey& key, int dx, int dy, int dz) { return at(offset(key, dx, dy, dz)); }

  static octomap::OcTreeKey offset(const octomap::OcTreeKey& key, int dx, int dy, int dz) {
    return octomap::OcTreeKey(static_cast<octomap::key_type>(key[0] + dx), static_cast<octomap::key_type>(key[1] + dy),
                              static_cast<octomap::key_type>(key[2] + dz));
  }

 private:
  // Index in bricks_ of the brick holding `key`, fetched from the octree on first use.
  uint32_t slot_of(const octomap::OcTreeKey& key) {
    const uint64_t brick_key = pack_key(octomap::OcTreeKey(key[0] >> 2, key[1] >> 2, key[2] >> 2));
    bool inserted = false;
    uint32_t& slot = index_.find_or_insert(brick_key, 0, inserted);
    if (inserted) {
      const uint32_t fetched = fetch(key);
      // find_or_insert's reference stays valid: fetch() does not touch the index.
      slot = fetched;
      last_key_ = ~uint64_t{0};  // bricks_ may have moved
    }
    return slot;
  }

  uint32_t fetch(const octomap::OcTreeKey& key) {
    const uint32_t slot = static_cast<uint32_t>(bricks_.size());
    bricks_.emplace_back();
    Brick& brick = bricks_.back();
    brick.fill(nullptr);
    const VoxelNode* node = tree_.search(key, tree_.getTreeDepth() - 2);
    if (node == nullptr || !tree_.nodeHasChildren(node)) return slot;
    // Child index bits are (x, y, z) = (1, 2, 4) of the key bit at that level.
    for (unsigned c = 0; c < 8; ++c) {
      if (!tree_.nodeChildExists(node, c)) continue;
      const VoxelNode* child = tree_.getNodeChild(node, c);
      for (unsigned g = 0; g < 8; ++g) {
        if (!tree_.nodeChildExists(child, g)) continue;
        const unsigned x = ((c & 1) << 1) | (g & 1);
        const unsigned y = (((c >> 1) & 1) << 1) | ((g >> 1) & 1);
        const unsigned z = (((c >> 2) & 1) << 1) | ((g >> 2) & 1);
        brick[x | (y << 2) | (z << 4)] = const_cast<VoxelNode*>(tree_.getNodeChild(child, g));
      }
    }
    return slot;
  }

  const VoxelOcTree& tree_;
  std::vector<Brick>& bricks_;
  FlatKeyMap<uint32_t>& index_;
  uint64_t last_key_ = ~uint64_t{0};
  Brick* last_ = nullptr;
};

}  // namespace hexplore::perception
