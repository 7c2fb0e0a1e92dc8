#include "common/perception/voxel_octree.h"

namespace hexplore::perception {

VoxelOcTree::VoxelOcTree(double resolution)
    : octomap::OcTreeBaseImpl<VoxelNode, octomap::AbstractOcTree>(resolution) {}

VoxelNode* VoxelOcTree::find_or_create(const octomap::OcTreeKey& key, bool& created) {
  created = false;
  if (root == nullptr) {
    root = new VoxelNode();
    ++tree_size;
  }
  VoxelNode* node = root;
  for (int depth = static_cast<int>(tree_depth) - 1; depth >= 0; --depth) {
    const unsigned int child = octomap::computeChildIdx(key, depth);
    if (!nodeChildExists(node, child)) {
      createNodeChild(node, child);
      created = depth == 0;
    }
    node = getNodeChild(node, child);
  }
  return node;
}

}  // namespace hexplore::perception
