#pragma once
// Read-only attributes of one occupied voxel as the rest of the system sees them, and the
// paper's voxel-set partition (eq. 3 and 5) of such a voxel.

#include <cstdint>

#include <Eigen/Core>

#include "common/core/coverage_gap.h"
#include "common/perception/voxel_data.h"
#include "common/perception/voxel_octree.h"

namespace hexplore::perception {

struct VoxelView {
  core::GridCell key;
  uint32_t point_count = 0;
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();            // world frame, metres
  Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();      // of the voxel's own points
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();          // zero when unknown
  double slope_deg = 180.0;                                  // s(v); 180 when no normal
  double sparsity = 1.0;                                     // d(v): empty neighbours / 26
  // Observation metrics over qualifying observations (gamma < gamma_th, l < l_th).
  bool observed = false;
  double observation_angle_deg = 180.0;                      // gamma(v)
  double observation_distance_m = 1.0e9;                     // l(v)
  double observation_density = 0.0;                          // rho(v), points per cm^2
  core::CoverageGap coverage_gap = core::CoverageGap::kNoNormal;  // why not a CSE (kNone: it is)
  uint8_t flags = 0;                                         // kFlagGround | kFlagCovered | kFlagTraversable
  uint32_t low_risk_species_mask = 0;                        // bit k: R_k(v) = 0

  bool ground() const { return (flags & kFlagGround) != 0; }
  bool covered() const { return (flags & kFlagCovered) != 0; }          // Q(v) = 1: CSE
  bool traversable() const { return (flags & kFlagTraversable) != 0; }  // zeta(v) = 1
};

// The four subsets of eq. 5, and ground voxels no species can traverse (in none of them).
enum class VoxelSet { kFacadeCovered, kFacadeIncomplete, kGroundCovered, kGroundIncomplete, kUntraversableGround };

inline VoxelSet partition(const VoxelView& v) {
  if (!v.ground()) return v.covered() ? VoxelSet::kFacadeCovered : VoxelSet::kFacadeIncomplete;
  if (!v.traversable()) return VoxelSet::kUntraversableGround;
  return v.covered() ? VoxelSet::kGroundCovered : VoxelSet::kGroundIncomplete;
}

}  // namespace hexplore::perception
