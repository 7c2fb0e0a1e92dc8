// What the wire conversions refuse: positions and normals that no map can hold. Each case is
// an input tests/fuzz found to be undefined behaviour further in (grid cells of a 3.7e19 m
// centre in the topology graph, micrometre sums of a 3.5e13 m voxel mean in the segmenter).

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "common/highlevel/map_proto.h"

namespace hexplore::highlevel {
namespace {

v1::Supervoxel supervoxel(uint64_t key, float x, float nz) {
  v1::Supervoxel s;
  s.set_key(key);
  s.set_center_x(x);
  s.set_center_y(2.0f);
  s.set_normal_z(nz);
  s.set_surface(v1::SURFACE_CLASS_GROUND);
  s.set_traversal_requirement(1);
  s.set_voxel_count(10);
  return s;
}

TEST(MapProto, SupervoxelsOffTheWorldOrWithoutAUnitNormalAreLeftOutAndCounted) {
  v1::MapIncrement inc;
  inc.set_source_robot("mr1000a");
  inc.set_increment_seq(1);
  *inc.add_supervoxels() = supervoxel(1, 3.0f, 1.0f);
  *inc.add_supervoxels() = supervoxel(2, -3.69633e19f, 1.0f);
  *inc.add_supervoxels() = supervoxel(3, std::numeric_limits<float>::quiet_NaN(), 1.0f);
  *inc.add_supervoxels() = supervoxel(4, 3.0f, std::numeric_limits<float>::infinity());
  *inc.add_supervoxels() = supervoxel(5, 3.0f, 7.0f);
  const SourcedUpdate u = from_proto(inc);
  ASSERT_EQ(u.update.upserts.size(), 1u);
  EXPECT_EQ(u.update.upserts[0].key, 1u);
  EXPECT_EQ(u.update.malformed, 4u);
}

TEST(MapProto, OutOfRangeNumbersBecomeTheStrictestReading) {
  v1::Supervoxel s = supervoxel(1, 3.0f, 1.0f);
  s.set_traversal_requirement(0xFFFFFFFFu);  // as an int: -1, which every level would pass
  s.set_voxel_count(0xFFFFFFF0u);
  s.set_covered_voxels(0xFFFFFFFFu);
  s.set_surface(static_cast<v1::SurfaceClass>(77));
  const Supervoxel sv = from_proto(s);
  EXPECT_GT(sv.traversal_requirement, 1000);
  EXPECT_GT(sv.voxel_count, 0);
  EXPECT_LE(sv.covered_voxels, sv.voxel_count);
  EXPECT_EQ(sv.surface, surface_of_key(1));
}

TEST(MapProto, VoxelsOffTheWorldOrWithoutAUnitNormalAreLeftOutAndCounted) {
  v1::VoxelDelta delta;
  delta.set_resolution_m(0.15);
  auto add = [&](float mean_x, float normal_z) {
    v1::Voxel* v = delta.add_voxels();
    v->set_ix(10);
    v->set_mean_x(mean_x);
    v->set_normal_z(normal_z);
  };
  add(1.5f, 1.0f);
  add(3.5e13f, 1.0f);
  add(1.5f, std::numeric_limits<float>::quiet_NaN());
  add(1.5f, 0.0f);  // no normal yet: kept
  size_t malformed = 0;
  const auto samples = voxel_samples(delta, &malformed);
  EXPECT_EQ(samples.size(), 2u);
  EXPECT_EQ(malformed, 2u);
}

}  // namespace
}  // namespace hexplore::highlevel
