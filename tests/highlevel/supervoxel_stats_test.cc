#include "common/highlevel/supervoxel_stats.h"

#include <cmath>

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

TEST(SupervoxelStats, AnIncompleteFacadeIsLocatedAndOrientedByItsIncompleteVoxels) {
  // A wall facing -y: its left half complete, its right half incomplete and leaning up by 40 deg
  // (an edge the first view met beyond the angle threshold).
  const Eigen::Vector3f leaning = Eigen::Vector3f(0.0f, -std::cos(0.7f), std::sin(0.7f));
  VoxelSetStats s;
  for (int i = 0; i < 4; ++i) {
    VoxelSample v;
    v.mean = {0.15f * float(i), 0.0f, 1.0f};
    const bool covered = i < 2;
    const Eigen::Vector3f n = covered ? Eigen::Vector3f(0.0f, -1.0f, 0.0f) : leaning;
    v.normal = {n.x(), n.y(), n.z()};
    v.flags = covered ? kVoxelCovered : 0u;
    v.gap = covered ? core::CoverageGap::kNone : core::CoverageGap::kAngle;
    s.add(v, +1, 1);
  }
  const uint64_t facade = supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kMinusY);
  const Supervoxel open = supervoxel_from(facade, s, true, {1});
  ASSERT_FALSE(open.covered);
  EXPECT_NEAR(open.center.x(), 0.375, 1e-6);  // the mean of the two incomplete voxels, not 0.225
  EXPECT_NEAR(open.normal.dot(leaning.cast<double>().normalized()), 1.0, 1e-6);
  // Without an ISE patch it counts as covered and is located by all its voxels again.
  const Supervoxel covered = supervoxel_from(facade, s, false, {1});
  EXPECT_NEAR(covered.center.x(), 0.225, 1e-6);
  // Ground stays where all its voxels are: it is a topology vertex.
  const Supervoxel ground = supervoxel_from(supervoxel_key({0, 0, 0}, SurfaceClass::kGround), s, true, {1});
  EXPECT_NEAR(ground.center.x(), 0.225, 1e-6);
}

}  // namespace
}  // namespace hexplore::highlevel
