#include "common/sim/ground_truth.h"

#include <gtest/gtest.h>

#include <random>

#include "common/sim/mesh_builder.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"

namespace hexplore::sim {
namespace {

TriangleMesh small_world() {
  MeshBuilder b;
  b.plane(-10, -10, 10, 10, 0.0);
  b.box({2, 2, 0}, {4, 4, 1});      // a block to look at, lower than the sensor
  b.box({-6, -6, 0}, {-4, -4, 3});  // a sealed hut...
  b.box({-5.8, -5.8, 0.01}, {-4.2, -4.2, 2.5});  // ...with something inside nobody can see
  return b.take();
}

TEST(GroundTruth, SamplesAreAreaWeightedAndDeterministic) {
  const TriangleMesh mesh = small_world();
  const auto a = sample_surface(mesh, 0.1, 1), b = sample_surface(mesh, 0.1, 1), c = sample_surface(mesh, 0.1, 2);
  EXPECT_NEAR(static_cast<double>(a.points.size()), mesh.surface_area() / 0.01, 0.02 * mesh.surface_area() / 0.01);
  EXPECT_TRUE(a.points == b.points);
  EXPECT_FALSE(a.points == c.points);
  const Eigen::AlignedBox3d crop(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(10, 10, 5));
  const auto cropped = sample_surface(mesh, 0.1, 1, &crop);
  for (const auto& p : cropped.points) EXPECT_TRUE(crop.contains(p.cast<double>()));
}

TEST(GroundTruth, CompletenessOfTheSamplesThemselvesIsFullAndOfAnEmptyMapZero) {
  const auto samples = sample_surface(small_world(), 0.1, 1);
  const VoxelSet full = VoxelSet::from_points(0.15, samples.points);
  EXPECT_NEAR(completeness(samples, full).fraction, 1.0, 1e-12);
  EXPECT_EQ(completeness(samples, VoxelSet(0.15)).fraction, 0.0);
  // Half the ground mapped: about half of the ground samples covered.
  std::vector<Eigen::Vector3f> half;
  for (const auto& p : samples.points)
    if (p.x() < 0) half.push_back(p);
  const double f = completeness(samples, VoxelSet::from_points(0.15, half)).fraction;
  EXPECT_GT(f, 0.3);
  EXPECT_LT(f, 0.7);
}

TEST(GroundTruth, CompletenessCountsExactlyTheSamplesNearAnOccupiedVoxel) {
  // The evaluation's dense bit grid must agree with VoxelSet::near sample by sample, also for
  // voxels outside the samples' box, negative cells and a mask.
  const auto samples = sample_surface(small_world(), 0.1, 3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> x(-12.f, 12.f), z(-1.f, 4.f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 4000; ++i) points.emplace_back(x(rng), x(rng), z(rng));
  const VoxelSet map = VoxelSet::from_points(0.15, points);
  std::vector<uint8_t> mask(samples.points.size());
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = (i % 3) != 0;
  size_t near_all = 0, near_masked = 0, masked = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const bool near = map.near(samples.points[i]);
    near_all += near;
    if (mask[i]) {
      ++masked;
      near_masked += near;
    }
  }
  ASSERT_GT(near_all, 100u);
  EXPECT_EQ(completeness(samples, map).covered, near_all);
  EXPECT_EQ(completeness(samples, map, &mask).covered, near_masked);
  EXPECT_EQ(completeness(samples, map, &mask).total, masked);
}

TEST(GroundTruth, VoxelKeysMatchTheWireFormat) {
  const std::vector<int32_t> keys = {0, 0, 0, -1, 2, 3};
  const VoxelSet s = VoxelSet::from_keys(0.2, keys);
  EXPECT_EQ(s.size(), 2u);
  EXPECT_TRUE(s.near(Eigen::Vector3f(0.1f, 0.1f, 0.1f)));
  EXPECT_TRUE(s.near(Eigen::Vector3f(0.3f, 0.1f, 0.1f)));   // neighbour voxel
  EXPECT_FALSE(s.near(Eigen::Vector3f(0.5f, 0.1f, 0.1f)));  // two voxels away
  EXPECT_TRUE(s.near(Eigen::Vector3f(-0.1f, 0.5f, 0.7f)));
}

TEST(Observability, HiddenSurfacesAreNotObservable) {
  const TriangleMesh mesh = small_world();
  const RayCaster caster(mesh);
  const auto samples = sample_surface(mesh, 0.2, 1);
  core::TeamConfig team;
  team.species = {core::builtin_mr1000()};
  core::RobotConfig r;
  r.id = "a";
  r.species = "MR1000";
  r.start_position_m = {0, -8, 0};
  team.robots = {r};
  const Eigen::AlignedBox3d region(Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(10, 10, 5));
  ObservabilityOptions opt;
  opt.grid_m = 1.0;
  const auto reach = reachable_ground(caster, team.species[0], std::vector<Eigen::Vector3d>{r.start_position_m}, region, opt);
  EXPECT_GT(reach.size(), 200u);
  for (const auto& p : reach) EXPECT_FALSE(p.x() > 2 && p.x() < 4 && p.y() > 2 && p.y() < 4);  // not on the block
  ObservableCache cache;
  int computed = 0;
  auto compute = [&] {
    ++computed;
    return observable_mask(caster, samples, team, region, opt);
  };
  const auto key = observability_key("small", 1, team);
  const auto mask = cache.get(key, compute);
  EXPECT_EQ(cache.get(key, compute), mask);
  EXPECT_EQ(computed, 1);
  size_t inner = 0, inner_seen = 0, block_top = 0, block_top_seen = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const auto& p = samples.points[i];
    if (p.x() > -5.7 && p.x() < -4.3 && p.y() > -5.7 && p.y() < -4.3 && p.z() > 0.005 && p.z() < 2.9) {
      ++inner;
      inner_seen += (*mask)[i];
    }
    if (p.x() > 2.05 && p.x() < 3.95 && p.y() > 2.05 && p.y() < 3.95 && std::abs(p.z() - 1.0) < 1e-3) {
      ++block_top;
      block_top_seen += (*mask)[i];
    }
  }
  EXPECT_GT(inner, 50u);
  EXPECT_EQ(inner_seen, 0u);                     // inside the sealed hut
  EXPECT_GT(block_top_seen, block_top * 9 / 10);  // seen from the wheeled robot's sensor above it
  const auto all = completeness(samples, VoxelSet::from_points(0.15, samples.points), mask.get());
  EXPECT_NEAR(all.fraction, 1.0, 1e-12);
  EXPECT_LT(all.total, samples.points.size());
}

}  // namespace
}  // namespace hexplore::sim
