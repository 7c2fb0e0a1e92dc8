#pragma once
// One perception-map voxel as the high-level map sees it: a plain mirror of hexplore.v1.Voxel
// so the segmentation has no protobuf or socket dependency (conversion in map_proto.h).

#include <cstdint>

#include <Eigen/Core>

#include "common/core/coverage_gap.h"
#include "common/core/seed_key.h"

namespace hexplore::highlevel {

// Bit flags of a voxel; values equal hexplore.v1.VoxelFlag.
enum VoxelFlag : uint32_t {
  kVoxelGround = 1,       // slope < s_th (else facade)
  kVoxelCovered = 2,      // Q(v) = 1: complete surface element
  kVoxelTraversable = 4,  // zeta(v) = 1: low risk for at least one species
  kVoxelRemoved = 8,      // no longer occupied
};

struct VoxelSample {
  core::GridCell key;                            // integer key at the map resolution
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();    // Gaussian mean, metres
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ(); // unit surface normal
  uint32_t flags = 0;                            // VoxelFlag bits
  uint32_t low_risk_species_mask = 0;            // bit k: low risk for species index k
  core::CoverageGap gap = core::CoverageGap::kNone;  // why it is not covered

  bool removed() const { return (flags & kVoxelRemoved) != 0; }
  bool covered() const { return (flags & kVoxelCovered) != 0; }
  // Traversable ground (G in the paper): ground slope and low risk for some species. These
  // voxels form ground supervoxels; every other voxel (facades, ground no species can cross)
  // forms facade supervoxels.
  bool traversable_ground() const {
    return (flags & kVoxelGround) != 0 && low_risk_species_mask != 0;
  }
};

}  // namespace hexplore::highlevel
