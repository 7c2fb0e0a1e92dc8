#include "common/highlevel/supervoxel_stats.h"

#include <cmath>

namespace hexplore::highlevel {

void VoxelSetStats::add(const VoxelSample& v, int sign, size_t species) {
  if (low_risk.size() < species) low_risk.resize(species, 0);
  count += sign;
  if (v.covered()) covered += sign;
  else gaps[size_t(v.gap)] += sign;
  for (int i = 0; i < 3; ++i) {
    const int64_t m = sign * std::llround(double{v.mean[i]} * 1e6);
    const int64_t nn = sign * std::llround(double{v.normal[i]} * 1e6);
    mean_um[i] += m;
    normal_u[i] += nn;
    if (!v.covered()) {
      open_mean_um[i] += m;
      open_normal_u[i] += nn;
    }
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
    open_mean_um[i] += s.open_mean_um[i];
    open_normal_u[i] += s.open_normal_u[i];
  }
  for (size_t k = 0; k < s.low_risk.size(); ++k) low_risk[k] += s.low_risk[k];
}

namespace {

Eigen::Vector3d mean_position(const int64_t (&sum_um)[3], int64_t n) {
  const double count = static_cast<double>(n);
  return Eigen::Vector3d(sum_um[0] / count, sum_um[1] / count, sum_um[2] / count) * 1e-6;
}

// The direction of a sum of unit vectors; `otherwise` when they cancel out.
Eigen::Vector3d mean_direction(const int64_t (&sum_u)[3], const Eigen::Vector3d& otherwise) {
  const Eigen::Vector3d sum(static_cast<double>(sum_u[0]), static_cast<double>(sum_u[1]), static_cast<double>(sum_u[2]));
  return sum.norm() > 0.0 ? Eigen::Vector3d(sum.normalized()) : otherwise;
}

}  // namespace

Supervoxel supervoxel_from(uint64_t key, const VoxelSetStats& total, bool has_ise_patch, const std::vector<int>& levels) {
  Supervoxel sv;
  sv.key = key;
  sv.surface = surface_of_key(key);
  sv.voxel_count = static_cast<int>(total.count);
  if (total.count == 0) return sv;
  sv.covered = total.covered == total.count || !has_ise_patch;
  sv.covered_voxels = static_cast<int>(total.covered);
  // An incomplete facade is where its incomplete voxels are and faces the way they face: the
  // paper segments the ISE voxels on their own, so its ISE supervoxel (the coverage target) is
  // made of them. Located by all its voxels, a wall patch whose edge voxels failed on the angle
  // kept the mean normal its first view had met, so every view along the same line passed J
  // again and failed again (common/planning/README.md, "Targets located by what is left of them").
  // Ground keeps the centre of all its voxels: it is a topology vertex.
  sv.center = mean_position(total.mean_um, total.count);
  sv.normal = mean_direction(total.normal_u, Eigen::Vector3d::UnitZ());
  const int64_t open = total.count - total.covered;
  if (!sv.covered && sv.facade() && open > 0) {
    sv.center = mean_position(total.open_mean_um, open);
    sv.normal = mean_direction(total.open_normal_u, sv.normal);
  }
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
