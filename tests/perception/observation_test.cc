// Observation metrics and coverage Q(v) (eq. 2): ISE until a close, frontal, dense observation.

#include <map>

#include <gtest/gtest.h>

#include "tests/perception/synthetic_scene.h"

namespace hexplore::perception {
namespace {

using testing::add_patch;
using testing::scan_of;
using testing::two_species_params;

// A 3 m x 2 m wall in the plane y = 0, facing +y.
std::vector<float> wall(double spacing) {
  std::vector<float> pts;
  add_patch(pts, {0, 0, 0}, {3, 0, 0}, {0, 0, 2}, spacing);
  return pts;
}

bool interior(const VoxelView& v) {
  return v.mean.x() > 0.3 && v.mean.x() < 2.7 && v.mean.z() > 0.3 && v.mean.z() < 1.7;
}

TEST(Observation, FarGrazingViewLeavesIseUntilCloseFrontalDenseView) {
  PerceptionMap map(two_species_params());  // SLUGCAT: l_th = 10 m
  const std::vector<float> sparse = wall(0.05);
  map.integrate(scan_of(sparse, {-20, 1, 1}), {});  // 20 m away, ~87 deg from the normal
  int checked = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!interior(v)) continue;
    ++checked;
    EXPECT_FALSE(v.observed);
    EXPECT_FALSE(v.covered());
    EXPECT_EQ(partition(v), VoxelSet::kFacadeIncomplete);
  }
  EXPECT_GT(checked, 100);

  const std::vector<float> dense = wall(0.01);
  map.integrate(scan_of(dense, {1.5, 3, 1}), {});  // 3 m in front
  checked = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!interior(v)) continue;
    ++checked;
    EXPECT_TRUE(v.observed);
    EXPECT_LT(v.observation_angle_deg, 45.0);
    EXPECT_LT(v.observation_distance_m, 3.5);
    EXPECT_GT(v.observation_density, 0.3);
    EXPECT_TRUE(v.covered());
    EXPECT_EQ(partition(v), VoxelSet::kFacadeCovered);
  }
  EXPECT_GT(checked, 100);
}

TEST(Observation, CloseFrontalButSparseStaysIse) {
  PerceptionMap map(two_species_params());
  const std::vector<float> sparse = wall(0.05);  // ~9 points per voxel: 0.04 points/cm^2
  map.integrate(scan_of(sparse, {1.5, 3, 1}), {});
  for (const VoxelView& v : map.voxels()) {
    if (!interior(v)) continue;
    EXPECT_TRUE(v.observed);
    EXPECT_LT(v.observation_density, 0.3);
    EXPECT_FALSE(v.covered());
  }
}

TEST(Observation, DistanceThresholdIsTheOwnSpeciesRange) {
  // 15 m frontal and dense: beyond SLUGCAT's 10 m, within MR1000's 27 m.
  const std::vector<float> dense = wall(0.01);
  PerceptionMap slugcat(two_species_params(core::builtin_slugcat()));
  PerceptionMap mr1000(two_species_params(core::builtin_mr1000()));
  slugcat.integrate(scan_of(dense, {1.5, 15, 1}), {});
  mr1000.integrate(scan_of(dense, {1.5, 15, 1}), {});
  for (const VoxelView& v : slugcat.voxels()) {
    if (interior(v)) {
      EXPECT_FALSE(v.covered());
    }
  }
  for (const VoxelView& v : mr1000.voxels()) {
    if (interior(v)) {
      EXPECT_TRUE(v.covered());
    }
  }
}

TEST(Observation, OnlyObservationsInsideTheThresholdsSetTheMinima) {
  PerceptionMap map(two_species_params());
  const std::vector<float> dense = wall(0.01);
  map.integrate(scan_of(dense, {1.5, 3, 1}), {});
  const core::GridCell key = map.key_of({1.5, 0, 1.0});
  const double angle = map.find(key)->observation_angle_deg;
  // Closer but at a grazing angle: must not replace the distance.
  map.integrate(scan_of(dense, {-1.0, 0.5, 1}), {});
  EXPECT_NEAR(map.find(key)->observation_distance_m, 3.0, 0.05);
  EXPECT_DOUBLE_EQ(map.find(key)->observation_angle_deg, angle);
}

}  // namespace
}  // namespace hexplore::perception

namespace hexplore::perception {
namespace {

// Ground uses its own angle threshold (gamma_th_ground, 75 deg by default): a robot's LiDAR
// sees the floor near it at 60-75 deg, which must count, while far floor stays ISE.
TEST(Observation, GroundNearTheSensorIsCoveredAtGrazingAnglesFarGroundIsNot) {
  PerceptionMap map(testing::two_species_params());
  std::vector<float> floor;
  testing::add_patch(floor, {-4, -4, 0}, {8, 0, 0}, {0, 8, 0}, 0.01);
  map.integrate(testing::scan_of(floor, {0, 0, 0.6}), {});
  int near_checked = 0, far_checked = 0;
  for (const VoxelView& v : map.voxels()) {
    const double d = std::hypot(v.mean.x(), v.mean.y());
    if (!v.ground()) continue;
    if (d > 0.8 && d < 1.6) {  // 53-70 deg from the normal
      ++near_checked;
      EXPECT_TRUE(v.covered()) << "at " << d << " m";
    } else if (d > 3.0 && d < 3.8) {  // beyond 78 deg
      ++far_checked;
      EXPECT_FALSE(v.covered()) << "at " << d << " m";
    }
  }
  EXPECT_GT(near_checked, 50);
  EXPECT_GT(far_checked, 50);
}

// rho(v) is the density of the voxel's point cloud: points from grazing looks count too, so
// one frontal look completes what grazing ones filled; counting qualifying points only, the
// frontal look must bring the whole density itself.
TEST(Observation, DensityCountsEveryPointOfTheVoxelUnlessConfiguredOtherwise) {
  for (const bool all : {true, false}) {
    MapParams p = two_species_params();
    EXPECT_EQ(p.density, MapParams::Density::kAllPoints);  // the team default
    p.density = all ? MapParams::Density::kAllPoints : MapParams::Density::kQualifyingPoints;
    PerceptionMap map(p);
    map.integrate(scan_of(wall(0.01), {-6, 1, 1}), {});   // dense, grazing
    map.integrate(scan_of(wall(0.05), {1.5, 3, 1}), {});  // sparse, frontal
    int complete = 0, interior_voxels = 0;
    for (const VoxelView& v : map.voxels()) {
      if (!interior(v)) continue;
      ++interior_voxels;
      complete += v.covered() ? 1 : 0;
    }
    ASSERT_GT(interior_voxels, 100);
    if (all) EXPECT_GT(complete, interior_voxels * 9 / 10) << "every point counts";
    else EXPECT_EQ(complete, 0) << "qualifying points only";
  }
}

// A wall that runs along a voxel boundary splits its points between two layers of voxels, so
// counted per voxel face each layer holds half the density the sensor delivered and stays an
// ISE however long it is observed. Counted per area of the surface fitted to the voxel's
// neighbourhood (fused_surface) the density is the delivered one, and a sparse wall stays sparse.
TEST(Observation, FusedSurfaceDensityIsThePointsPerAreaWhereAWallSplitsAcrossVoxels) {
  // 0.5 points/cm^2 on the plane y = 0 (a voxel boundary), points alternating 4 mm either side.
  auto split_wall = [](double spacing) {
    std::vector<float> pts = wall(spacing);
    for (size_t i = 0; i < pts.size() / 3; ++i) pts[3 * i + 1] = (i % 2 == 0) ? 0.004f : -0.004f;
    return pts;
  };
  const double dense_spacing = 1.0 / std::sqrt(0.5e4);  // 0.5 points/cm^2
  for (const auto density : {MapParams::Density::kAllPoints, MapParams::Density::kFusedSurface}) {
    MapParams p = two_species_params();
    p.density = density;
    PerceptionMap map(p);
    map.integrate(scan_of(split_wall(dense_spacing), {1.5, 3, 1}), {});
    int interior_voxels = 0, complete = 0;
    for (const VoxelView& v : map.voxels()) {
      if (!interior(v)) continue;
      ++interior_voxels;
      complete += v.covered() ? 1 : 0;
      if (density == MapParams::Density::kFusedSurface) {
        EXPECT_NEAR(v.observation_density, 0.5, 0.1);
      }
    }
    ASSERT_GT(interior_voxels, 200) << "both layers of voxels hold points";
    if (density == MapParams::Density::kAllPoints) EXPECT_EQ(complete, 0) << "half the points per voxel face";
    else EXPECT_EQ(complete, interior_voxels);
  }
  MapParams p = two_species_params();
  p.density = MapParams::Density::kFusedSurface;
  PerceptionMap sparse(p);
  sparse.integrate(scan_of(split_wall(0.05), {1.5, 3, 1}), {});  // 0.04 points/cm^2
  for (const VoxelView& v : sparse.voxels()) {
    if (!interior(v)) continue;
    EXPECT_NEAR(v.observation_density, 0.04, 0.01);
    EXPECT_FALSE(v.covered());
  }
}

// The coverage gap names the first unmet term of Q(v), so a user can tell "look from
// elsewhere" (angle, distance) from "look longer" (density).
TEST(Observation, CoverageGapNamesTheUnmetTerm) {
  auto interior_gaps = [](const PerceptionMap& map) {
    std::map<core::CoverageGap, int> n;
    for (const VoxelView& v : map.voxels())
      if (interior(v)) ++n[v.coverage_gap];
    return n;
  };
  const std::vector<float> dense = wall(0.01);
  {  // grazing only: angle
    PerceptionMap map(two_species_params());
    map.integrate(scan_of(dense, {-6, 1, 1}), {});
    const auto n = interior_gaps(map);
    EXPECT_GT(n.count(core::CoverageGap::kAngle) ? n.at(core::CoverageGap::kAngle) : 0, 100);
    EXPECT_EQ(n.count(core::CoverageGap::kNone), 0u);
  }
  {  // frontal but beyond SLUGCAT's 10 m: distance
    PerceptionMap map(two_species_params());
    map.integrate(scan_of(dense, {1.5, 15, 1}), {});
    const auto n = interior_gaps(map);
    EXPECT_GT(n.count(core::CoverageGap::kDistance) ? n.at(core::CoverageGap::kDistance) : 0, 100);
    EXPECT_EQ(n.count(core::CoverageGap::kNone), 0u);
  }
  {  // frontal, close, sparse: density; then dense: complete, and the gap is gone
    PerceptionMap map(two_species_params());
    map.integrate(scan_of(wall(0.05), {1.5, 3, 1}), {});
    auto n = interior_gaps(map);
    EXPECT_GT(n.count(core::CoverageGap::kDensity) ? n.at(core::CoverageGap::kDensity) : 0, 100);
    map.integrate(scan_of(dense, {1.5, 3, 1}), {});
    n = interior_gaps(map);
    EXPECT_GT(n.count(core::CoverageGap::kNone) ? n.at(core::CoverageGap::kNone) : 0, 100);
    EXPECT_EQ(n.count(core::CoverageGap::kDensity), 0u);
  }
}

TEST(Observation, AGapChangeIsPublished) {
  MapParams qualifying = two_species_params();
  qualifying.density = MapParams::Density::kQualifyingPoints;
  PerceptionMap map(qualifying);
  map.integrate(scan_of(wall(0.01), {-6, 1, 1}), {});  // grazing: angle
  map.take_changes();
  map.integrate(scan_of(wall(0.05), {1.5, 3, 1}), {});  // frontal, sparse: density (still ISE)
  int density = 0;
  for (const VoxelView& v : map.take_changes())
    if (interior(v) && v.coverage_gap == core::CoverageGap::kDensity) ++density;
  EXPECT_GT(density, 100);
}

}  // namespace
}  // namespace hexplore::perception
