#include "common/highlevel/supervoxel_stats.h"

#include <gtest/gtest.h>

namespace hexplore::highlevel {
namespace {

VoxelSample voxel(float x, bool covered, core::CoverageGap gap, uint32_t low_risk) {
  VoxelSample v;
  v.mean = {x, 0.0f, 0.0f};
  v.normal = {0.0f, 0.0f, 1.0f};
  v.flags = kVoxelGround | (covered ? kVoxelCovered : 0u);
  v.gap = covered ? core::CoverageGap::kNone : gap;
  v.low_risk_species_mask = low_risk;
  return v;
}

TEST(SupervoxelStats, AddingAndRemovingInAnyOrderGivesTheSameSums) {
  const VoxelSample a = voxel(0.1f, true, core::CoverageGap::kNone, 0b11);
  const VoxelSample b = voxel(0.3f, false, core::CoverageGap::kAngle, 0b10);
  const VoxelSample c = voxel(0.7f, false, core::CoverageGap::kDensity, 0b11);
  VoxelSetStats one, two;
  one.add(a, +1, 2), one.add(b, +1, 2), one.add(c, +1, 2), one.add(b, -1, 2);
  two.add(c, +1, 2), two.add(a, +1, 2);
  const Supervoxel x = supervoxel_from(7, one, true, {1, 2});
  const Supervoxel y = supervoxel_from(7, two, true, {1, 2});
  EXPECT_EQ(x.center, y.center);
  EXPECT_EQ(x.covered_voxels, 1);
  EXPECT_EQ(x.voxel_count, 2);
  EXPECT_NEAR(x.center.x(), 0.4, 1e-6);
  EXPECT_EQ(x.gap, core::CoverageGap::kDensity);
  EXPECT_EQ(x.traversal_requirement, 1);  // both voxels are low risk for species 0
}

TEST(SupervoxelStats, ASupervoxelWithoutAnIsePatchIsCovered) {
  VoxelSetStats s;
  s.add(voxel(0.0f, true, core::CoverageGap::kNone, 1), +1, 1);
  s.add(voxel(0.2f, false, core::CoverageGap::kAngle, 1), +1, 1);
  EXPECT_FALSE(supervoxel_from(1, s, true, {1}).covered);
  EXPECT_TRUE(supervoxel_from(1, s, false, {1}).covered);
  EXPECT_EQ(supervoxel_from(1, s, true, {1}).gap, core::CoverageGap::kAngle);
}

}  // namespace
}  // namespace hexplore::highlevel
