#include "common/highlevel/supervoxel_stats.h"

#include <cmath>

namespace hexplore::highlevel {

void VoxelSetStats::add(const VoxelSample& v, int sign, size_t species) {
  if (low_risk.size() < species) low_risk.resize(species, 0);
  count += sign;
  if (v.covered()) covered += sign;
  else gaps[size_t(v.gap)] += sign;
  for (int i = 0; i < 3; ++i) {
    mean_um[i] += sign * std::llround(double{v.mean[i]} * 1e6);
    normal_u[i] += sign * std::llround(double{v.normal[i]} * 1e6);
  }
  for (size_t k = 0; k < species && k < 32; ++k) {
    if ((v.low_risk_species_mask >> k) & 1u) low_risk[k] += sign;
  }
}

void VoxelSetStats::add(const VoxelSetStats& s) {
  if (low_risk.size() < s.low_risk.size()) low_risk.resize(s.low_risk.size(), 0);
  count += s.count;
  covered += s.covered;
  for (int g = 0; g < core::kCoverageGapCount; ++g) gaps[g] += s.gaps[g];
  for (int i = 0; i < 3; ++i) {
    mean_um[i] += s.mean_um[i];
    normal_u[i] += s.normal_u[i];
  }
  for (size_t k = 0; k < s.low_risk.size(); ++k) low_risk[k] += s.low_risk[k];
}

Supervoxel supervoxel_from(uint64_t key, const VoxelSetStats& total, bool has_ise_patch, const std::vector<int>& levels) {
  Supervoxel sv;
  sv.key = key;
  sv.surface = surface_of_key(key);
  sv.voxel_count = static_cast<int>(total.count);
  if (total.count == 0) return sv;
  const double n = static_cast<double>(total.count);
  sv.center = Eigen::Vector3d(total.mean_um[0] / n, total.mean_um[1] / n, total.mean_um[2] / n) * 1e-6;
  const Eigen::Vector3d normal(static_cast<double>(total.normal_u[0]), static_cast<double>(total.normal_u[1]),
                               static_cast<double>(total.normal_u[2]));
  sv.normal = normal.norm() > 0.0 ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d::UnitZ();
  sv.covered = total.covered == total.count || !has_ise_patch;
  sv.covered_voxels = static_cast<int>(total.covered);
  if (!sv.covered) {
    int best = 0;  // kNone: incomplete voxels that gave no reason (from an old peer)
    for (int g = 1; g < core::kCoverageGapCount; ++g)
      if (total.gaps[g] > total.gaps[best]) best = g;
    sv.gap = core::CoverageGap(best);
  }
  uint32_t mask = 0;
  for (size_t k = 0; k < total.low_risk.size() && k < 32; ++k) {
    if (total.low_risk[k] == total.count) mask |= 1u << k;
  }
  sv.traversal_requirement = traversal_requirement(mask, levels);
  return sv;
}

}  // namespace hexplore::highlevel
