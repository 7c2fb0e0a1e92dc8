// Which side a voxel's normal points to. The angle test takes |cos|, so the side matters for
// the high-level map: it picks the facing of the supervoxel a voxel joins, and views are made on
// the side the normal points to. A normal turned into a building makes a target whose views
// stand inside the wall: it is never completed and keeps the mission alive.

#include <gtest/gtest.h>

#include "tests/perception/synthetic_scene.h"

namespace hexplore::perception {
namespace {

using testing::add_patch;
using testing::scan_of;
using testing::two_species_params;

// The outer faces of a building's south-west corner: the building fills x >= 0, y >= 0. West
// face x = 0 (outward -x), south face y = 0 (outward -y), 3 m tall.
std::vector<float> west_face() {
  std::vector<float> pts;
  add_patch(pts, {0, 0, 0}, {0, 2, 0}, {0, 0, 3}, 0.02);
  return pts;
}
std::vector<float> south_face() {
  std::vector<float> pts;
  add_patch(pts, {0, 0, 0}, {2, 0, 0}, {0, 0, 3}, 0.02);
  return pts;
}

bool near_edge(const VoxelView& v) {
  return v.mean.x() < 0.35 && v.mean.y() < 0.35 && v.mean.z() > 0.5 && v.mean.z() < 2.5;
}

// Outward at a convex corner: no component into the solid beyond what the edge's fitted plane
// (which bisects the corner) needs.
bool points_out_of_the_building(const VoxelView& v) { return v.normal.x() + v.normal.y() < 0.0f; }

TEST(NormalOrientation, ACornerSeenAtAGrazingAngleKeepsItsOutwardNormal) {
  PerceptionMap map(two_species_params(core::builtin_mr1000()));
  std::vector<float> both = west_face();
  const std::vector<float> south = south_face();
  both.insert(both.end(), south.begin(), south.end());
  map.integrate(scan_of(both, {-4, -4, 1.5}), {});  // from the south-west: the edge frontally
  int edge = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!near_edge(v) || v.normal.isZero()) continue;
    ++edge;
    EXPECT_TRUE(points_out_of_the_building(v)) << "after the frontal scan, voxel at " << v.mean.transpose()
                                                  << " normal " << v.normal.transpose();
  }
  ASSERT_GT(edge, 10);

  // From the south-east the south face is seen and the west face is hidden behind the corner.
  // The edge voxels' fitted planes (diagonal) are seen from behind at ~70 deg: a grazing ray
  // that says nothing about which side of the edge is open.
  for (int i = 0; i < 3; ++i) map.integrate(scan_of(south, {8, -3, 1.5}), {});
  for (const VoxelView& v : map.voxels()) {
    if (!near_edge(v) || v.normal.isZero()) continue;
    EXPECT_TRUE(points_out_of_the_building(v)) << "after the grazing scans, voxel at " << v.mean.transpose()
                                                  << " normal " << v.normal.transpose();
  }
}

TEST(NormalOrientation, ACornerSeenFaceByFaceFacesOutwards) {
  // First the west face from the west, then the south face from the south-east: the edge voxels
  // the second scan creates get a plane fitted across both faces, seen from just behind it. Their
  // own points lie on the south face alone, in front of the sensor.
  PerceptionMap map(two_species_params(core::builtin_mr1000()));
  map.integrate(scan_of(west_face(), {-4, 1.0, 1.5}), {});
  for (int i = 0; i < 3; ++i) map.integrate(scan_of(south_face(), {8, -3, 1.5}), {});
  int edge = 0;
  for (const VoxelView& v : map.voxels()) {
    if (!near_edge(v) || v.normal.isZero()) continue;
    ++edge;
    EXPECT_TRUE(points_out_of_the_building(v)) << "voxel at " << v.mean.transpose() << " normal " << v.normal.transpose();
  }
  ASSERT_GT(edge, 10);
}

TEST(NormalOrientation, AWallSeenFromItsOtherSideTurnsToFaceTheSensor) {
  // A thin panel seen first from one side, then frontally from the other: both sides are open,
  // and the newest frontal view decides (a gate, a sheet of debris).
  PerceptionMap map(two_species_params(core::builtin_mr1000()));
  std::vector<float> panel;
  add_patch(panel, {0, 0, 0}, {3, 0, 0}, {0, 0, 3}, 0.02);
  map.integrate(scan_of(panel, {1.5, -3, 1.5}), {});
  for (int i = 0; i < 2; ++i) map.integrate(scan_of(panel, {1.5, 3, 1.5}), {});
  int checked = 0;
  for (const VoxelView& v : map.voxels()) {
    if (v.mean.x() < 0.5 || v.mean.x() > 2.5 || v.mean.z() < 0.5 || v.mean.z() > 2.5) continue;
    ++checked;
    EXPECT_GT(v.normal.y(), 0.9f) << "voxel at " << v.mean.transpose();
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace hexplore::perception
