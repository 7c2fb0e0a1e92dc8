#pragma once
// A supervoxel's attributes as exact sums over its voxels (paper "Supervoxel Data Structure"):
// integer sums of means, normals, covered voxels, coverage gaps and per-species low risk, so
// adding and removing voxels in any order gives the same supervoxel bit for bit.

#include <cstdint>
#include <vector>

#include "common/core/coverage_gap.h"
#include "common/highlevel/supervoxel.h"
#include "common/highlevel/voxel_sample.h"

namespace hexplore::highlevel {

struct VoxelSetStats {
  int64_t count = 0;
  int64_t covered = 0;
  int64_t mean_um[3] = {0, 0, 0};    // sum of Gaussian means, micrometres
  int64_t normal_u[3] = {0, 0, 0};   // sum of normals, 1e-6 units
  int64_t open_mean_um[3] = {0, 0, 0};   // the same two sums over the incomplete voxels only
  int64_t open_normal_u[3] = {0, 0, 0};
  std::vector<int64_t> low_risk;     // per species: voxels low-risk for it
  int64_t gaps[core::kCoverageGapCount] = {};  // voxels per coverage gap

  // Adds (sign +1) or removes (sign -1) one voxel; `species` = how many species to count.
  void add(const VoxelSample& v, int sign, size_t species);
  void add(const VoxelSetStats& s);
};

// The supervoxel `key` of a voxel set: centre = mean voxel mean, normal = mean normal (of
// its incomplete voxels only while an incomplete facade, the paper's ISE supervoxel),
// traversal requirement from the species `levels`, and covered unless it holds an ISE patch
// (`has_ise_patch`, which the caller judges: it needs the voxels' adjacency). An incomplete
// supervoxel's gap is the one most of its incomplete voxels share.
Supervoxel supervoxel_from(uint64_t key, const VoxelSetStats& total, bool has_ise_patch, const std::vector<int>& levels);

}  // namespace hexplore::highlevel
