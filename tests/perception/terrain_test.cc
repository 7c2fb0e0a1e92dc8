// Terrain metrics, traversal risk and the facade/ground partition on analytic geometry.

#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "tests/perception/synthetic_scene.h"

namespace hexplore::perception {
namespace {

using testing::add_floor;
using testing::add_patch;
using testing::kMr1000Bit;
using testing::kSlugcatBit;
using testing::scan_of;
using testing::two_species_params;

bool inside_xy(const VoxelView& v, double x0, double x1, double y0, double y1) {
  return v.mean.x() > x0 && v.mean.x() < x1 && v.mean.y() > y0 && v.mean.y() < y1;
}

TEST(Terrain, FlatFloorIsGroundTraversableByEverySpecies) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -3, 3, -3, 3, 0.05, 0.02);
  const IntegrationStats stats = map.integrate(scan_of(pts, {0, 0, 1}), {});
  EXPECT_EQ(stats.points_integrated, pts.size() / 3);
  int interior = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!inside_xy(v, -2.7, 2.7, -2.7, 2.7)) continue;
    ++interior;
    EXPECT_TRUE(v.ground());
    EXPECT_LT(v.slope_deg, 2.0);
    EXPECT_GT(v.normal.z(), 0.99f) << "normal must point up, towards the sensor";
    EXPECT_EQ(v.low_risk_species_mask, kSlugcatBit | kMr1000Bit);
    EXPECT_TRUE(v.traversable());
  }
  EXPECT_GT(interior, 1000);
}

TEST(Terrain, TwentyDegreeRampIsTraversableByTheTrackedSpeciesOnly) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  const double t = std::tan(20.0 * M_PI / 180.0);
  add_patch(pts, {0, -2, 0.05}, {4, 0, 4 * t}, {0, 4, 0}, 0.015);
  map.integrate(scan_of(pts, {2, 0, 3}), {});
  int interior = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!inside_xy(v, 0.5, 3.5, -1.5, 1.5)) continue;
    ++interior;
    EXPECT_TRUE(v.ground());
    EXPECT_NEAR(v.slope_deg, 20.0, 2.0);
    EXPECT_TRUE(v.low_risk_species_mask & kSlugcatBit) << "at " << v.mean.transpose();
    EXPECT_FALSE(v.low_risk_species_mask & kMr1000Bit) << "at " << v.mean.transpose();
  }
  EXPECT_GT(interior, 300);
}

TEST(Terrain, VerticalWallIsFacade) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_patch(pts, {2, -2, 0}, {0, 4, 0}, {0, 0, 2.5}, 0.02);
  map.integrate(scan_of(pts, {0, 0, 1}), {});
  int interior = 0;
  for (const VoxelView& v : map.voxels()) {
    if (v.mean.y() < -1.7 || v.mean.y() > 1.7 || v.mean.z() < 0.3 || v.mean.z() > 2.2) continue;
    ++interior;
    EXPECT_FALSE(v.ground());
    EXPECT_NEAR(v.slope_deg, 90.0, 2.0);
    EXPECT_LT(v.normal.x(), -0.99f) << "normal must face the sensor";
    EXPECT_EQ(v.low_risk_species_mask, 0u);
    EXPECT_EQ(partition(v), VoxelSet::kFacadeIncomplete);
  }
  EXPECT_GT(interior, 250);
}

// Lower floor at z = 0.05 for x < 0.07, upper floor at z = 0.20 beyond, riser between.
std::vector<float> step_scene(double height) {
  std::vector<float> pts;
  add_floor(pts, -2, 0.07, -1.5, 1.5, 0.05, 0.015);
  add_floor(pts, 0.07, 2, -1.5, 1.5, 0.05 + height, 0.015);
  add_patch(pts, {0.07, -1.5, 0.05}, {0, 3, 0}, {0, 0, height}, 0.015);
  return pts;
}

TEST(Terrain, FifteenCentimetreStepBlocksTheWheeledSpeciesButNotTheTrackedOne) {
  PerceptionMap map(two_species_params());
  const std::vector<float> pts = step_scene(0.15);
  map.integrate(scan_of(pts, {-1, 0, 1}), {});
  const core::GridCell low = map.key_of({-1.5, 0, 0.05});
  const core::GridCell high = map.key_of({1.5, 0, 0.2});
  EXPECT_TRUE(testing::reachable(map, low, high, kSlugcatBit));
  EXPECT_FALSE(testing::reachable(map, low, high, kMr1000Bit));
  // Away from the edge, both floors stay fine for the wheeled robot.
  EXPECT_TRUE(map.find(low)->low_risk_species_mask & kMr1000Bit);
  EXPECT_TRUE(map.find(high)->low_risk_species_mask & kMr1000Bit);
}

TEST(Terrain, LowStepIsTraversableByBoth) {
  PerceptionMap map(two_species_params());
  const std::vector<float> pts = step_scene(0.04);
  map.integrate(scan_of(pts, {-1, 0, 1}), {});
  const core::GridCell low = map.key_of({-1.5, 0, 0.05});
  const core::GridCell high = map.key_of({1.5, 0, 0.09});
  EXPECT_TRUE(testing::reachable(map, low, high, kSlugcatBit));
  EXPECT_TRUE(testing::reachable(map, low, high, kMr1000Bit));
}

TEST(Terrain, HalfMetreOverhangBlocksWheeledClearanceOnly) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -2, 2, -2, 2, 0.05, 0.02);
  add_floor(pts, -0.5, 0.5, -2, 2, 0.55, 0.02);  // slab underside, seen from below
  map.integrate(scan_of(pts, {-1.5, 0, 0.35}), {});
  int under = 0;
  for (const VoxelView& v : map.voxels()) {
    if (v.key.z == 3) {
      EXPECT_FALSE(v.ground()) << "an overhang seen from below faces down: facade";
      EXPECT_LT(v.normal.z(), -0.99f);
      continue;
    }
    if (!inside_xy(v, -0.35, 0.35, -1.7, 1.7)) continue;
    ++under;
    EXPECT_TRUE(v.ground());
    EXPECT_TRUE(v.low_risk_species_mask & kSlugcatBit) << "0.5 m is above SLUGCAT's 0.45 m body";
    EXPECT_FALSE(v.low_risk_species_mask & kMr1000Bit) << "0.5 m is below MR1000's 0.8 m body";
  }
  EXPECT_GT(under, 50);
  const core::GridCell open = map.key_of({-1.5, 0, 0.05});
  EXPECT_EQ(map.find(open)->low_risk_species_mask, kSlugcatBit | kMr1000Bit);
}

TEST(Terrain, FloorAtTheFootOfAWallIsNotTraversable) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -2, 2, -2, 2, 0.05, 0.02);
  add_patch(pts, {1.0, -2, 0.05}, {0, 4, 0}, {0, 0, 2}, 0.02);
  map.integrate(scan_of(pts, {0, 0, 1}), {});
  const auto next_to_wall = map.find(map.key_of({0.8, 0, 0.05}));
  ASSERT_TRUE(next_to_wall.has_value());
  EXPECT_EQ(next_to_wall->low_risk_species_mask, 0u);
  EXPECT_EQ(partition(*next_to_wall), VoxelSet::kUntraversableGround);
  EXPECT_EQ(map.find(map.key_of({-1, 0, 0.05}))->low_risk_species_mask, kSlugcatBit | kMr1000Bit);
}

TEST(Terrain, StairsAreClimbableByTheTrackedSpeciesOnly) {
  // Five 0.17 m risers with 0.30 m treads, then a landing.
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -2, 0.07, -1.2, 1.2, 0.05, 0.015);
  double x = 0.07;
  double z = 0.05;
  for (int i = 0; i < 5; ++i) {
    add_patch(pts, {x, -1.2, z}, {0, 2.4, 0}, {0, 0, 0.17}, 0.015);
    z += 0.17;
    add_floor(pts, x, x + (i == 4 ? 2.0 : 0.30), -1.2, 1.2, z, 0.015);
    x += 0.30;
  }
  map.integrate(scan_of(pts, {-1, 0, 1.5}), {});
  const core::GridCell bottom = map.key_of({-1.5, 0, 0.05});
  const core::GridCell top = map.key_of({x + 1.0, 0, z - 0.02});  // z = 0.9 sits on a cell border
  ASSERT_TRUE(map.find(top).has_value());
  EXPECT_TRUE(testing::reachable(map, bottom, top, kSlugcatBit));
  EXPECT_FALSE(testing::reachable(map, bottom, top, kMr1000Bit));
}

// A flight of eight 0.176 m risers on 0.30 m treads (30.5 deg) from z = 0.05 up to a landing.
struct Flight {
  std::vector<float> risers, treads;  // treads include the floor below and the landing
  double top_x = 0.0, top_z = 0.0;
};
Flight flight() {
  Flight f;
  add_floor(f.treads, -2, 0.07, -1.2, 1.2, 0.05, 0.015);
  double x = 0.07, z = 0.05;
  for (int i = 0; i < 8; ++i) {
    add_patch(f.risers, {x, -1.2, z}, {0, 2.4, 0}, {0, 0, 0.176}, 0.015);
    z += 0.176;
    add_floor(f.treads, x, x + (i == 7 ? 6.0 : 0.30), -1.2, 1.2, z, 0.015);
    x += 0.30;
  }
  f.top_x = x - 0.30;
  f.top_z = z;
  return f;
}

// Seen from its top landing, a staircase shows only its treads, and the sensor (0.55 m above
// the landing, 4 m on) lies below the flight's mean plane: its fitted normals used to be
// turned towards the sensor, i.e. down, and the flight a robot had just climbed became a
// ceiling (facade) in its map, cut off from the floor below. Treads seen from above face up.
TEST(Terrain, StairsSeenFromTheirTopLandingStayGround) {
  PerceptionMap map(two_species_params());
  const Flight f = flight();
  std::vector<float> all = f.treads;
  all.insert(all.end(), f.risers.begin(), f.risers.end());
  map.integrate(scan_of(all, {-1, 0, 0.55}), {});
  map.integrate(scan_of(f.treads, {f.top_x + 4.0, 0, f.top_z + 0.55}), {});
  int on_flight = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!inside_xy(v, 0.1, f.top_x - 0.1, -1.0, 1.0)) continue;
    ++on_flight;
    EXPECT_GT(v.normal.z(), 0.0f) << "at " << v.mean.transpose();
  }
  EXPECT_GT(on_flight, 200);
  const core::GridCell bottom = map.key_of({-1.5, 0, 0.05});
  const core::GridCell landing = map.key_of({f.top_x + 2.0, 0, f.top_z - 0.02});
  EXPECT_TRUE(testing::reachable(map, bottom, landing, kSlugcatBit));
}

// The floor right at the foot of a riser holds the riser's bottom in its own column: the
// surface rising there is a step (0.2 m: the tracked species' to take, not the wheeled one's),
// not an overhead obstacle 0.15 m up, which made the whole foot of every flight high risk.
TEST(Terrain, FloorAtTheFootOfARiserIsAStepNotAnOverhang) {
  PerceptionMap map(two_species_params());
  const std::vector<float> pts = step_scene(0.20);
  map.integrate(scan_of(pts, {-1, 0, 1}), {});
  int foot = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!inside_xy(v, 0.0, 0.07, -1.2, 1.2) || v.key.z != 0) continue;  // the column holding the riser
    ++foot;
    EXPECT_TRUE(v.low_risk_species_mask & kSlugcatBit) << "at " << v.mean.transpose();
    EXPECT_FALSE(v.low_risk_species_mask & kMr1000Bit) << "at " << v.mean.transpose();
  }
  EXPECT_GT(foot, 10);
}

// Voxel slopes are allowed half a step steeper over the body's length than the species'
// slope limit, the tolerance the simulated body gets (stair nosings): a voxel slope above
// 35 deg no longer cuts a 30 deg flight for SLUGCAT. Smooth ramps show the allowance: 38 deg
// is SLUGCAT's and 13 deg MR1000's (the sim lets both bodies climb them), 42 and 16 are not.
TEST(Terrain, SlopeAllowanceIsTheSimulatedBodysTolerance) {
  const MapParams params = two_species_params();
  EXPECT_NEAR(slope_allowance_deg(params.species[0]), 40.0, 0.1);  // atan(tan 35 + 0.125 / 0.9)
  EXPECT_NEAR(slope_allowance_deg(params.species[1]), 14.2, 0.1);  // atan(tan 12 + 0.04 / 1.0)
  SpeciesLimits no_body = params.species[0];
  no_body.body_length_m = 0.0;
  EXPECT_DOUBLE_EQ(slope_allowance_deg(no_body), 35.0);
  for (const auto& [deg, slugcat, mr1000] : {std::tuple{13.0, true, true}, std::tuple{16.0, true, false},
                                             std::tuple{38.0, true, false}, std::tuple{42.0, false, false}}) {
    PerceptionMap map(params);
    std::vector<float> pts;
    const double t = std::tan(deg * M_PI / 180.0);
    add_patch(pts, {0, -2, 0.05}, {2.5, 0, 2.5 * t}, {0, 4, 0}, 0.015);
    map.integrate(scan_of(pts, {1.25, 0, 3}), {});
    int interior = 0;
    for (const VoxelView& v : map.voxels()) {
      if (!inside_xy(v, 0.5, 2.0, -1.5, 1.5)) continue;
      ++interior;
      EXPECT_EQ((v.low_risk_species_mask & kSlugcatBit) != 0, slugcat) << deg << " deg at " << v.mean.transpose();
      EXPECT_EQ((v.low_risk_species_mask & kMr1000Bit) != 0, mr1000) << deg << " deg at " << v.mean.transpose();
    }
    EXPECT_GT(interior, 100) << deg;
  }
}

TEST(Terrain, IncrementalIntegrationMatchesOneShot) {
  // The step scene delivered as ten interleaved partial scans ends where one full scan does.
  const std::vector<float> pts = step_scene(0.15);
  PerceptionMap once(two_species_params());
  once.integrate(scan_of(pts, {-1, 0, 1}), {});
  PerceptionMap incremental(two_species_params());
  for (int part = 0; part < 10; ++part) {
    std::vector<float> subset;
    for (size_t i = part; i < pts.size() / 3; i += 10) subset.insert(subset.end(), &pts[3 * i], &pts[3 * i + 3]);
    incremental.integrate(scan_of(subset, {-1, 0, 1}), {});
  }
  const std::vector<VoxelView> a = once.voxels();
  const std::vector<VoxelView> b = incremental.voxels();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].key, b[i].key);
    EXPECT_EQ(a[i].point_count, b[i].point_count);
    EXPECT_LT((a[i].mean - b[i].mean).norm(), 1e-4f);
    EXPECT_GT(a[i].normal.dot(b[i].normal), 0.999f);
    EXPECT_EQ(a[i].flags & ~kFlagCovered, b[i].flags & ~kFlagCovered) << "at " << a[i].mean.transpose();
    EXPECT_EQ(a[i].low_risk_species_mask, b[i].low_risk_species_mask) << "at " << a[i].mean.transpose();
  }
}

TEST(Terrain, ParamsRejectBadValues) {
  MapParams p = two_species_params();
  p.resolution_m = 0.0;
  EXPECT_THROW(PerceptionMap{p}, std::invalid_argument);
  p = two_species_params();
  p.species.clear();
  EXPECT_THROW(PerceptionMap{p}, std::invalid_argument);
  EXPECT_DOUBLE_EQ(two_species_params(core::builtin_mr1000()).l_th_m, 27.0);
}

}  // namespace
}  // namespace hexplore::perception
