#include "common/sim/ray_caster.h"

#include <gtest/gtest.h>

#include "common/sim/mesh_builder.h"
#include "common/sim/proxy_box.h"
#include "common/sim/scene_error.h"

namespace hexplore::sim {
namespace {

// A closed 10 x 10 x 3 m room (walls 0.2 m) on a ground plane.
TriangleMesh room() {
  MeshBuilder b;
  b.plane(-20, -20, 20, 20, 0.0);
  b.box({-5, -5, 0}, {5, -4.8, 3});
  b.box({-5, 4.8, 0}, {5, 5, 3});
  b.box({-5, -4.8, 0}, {-4.8, 4.8, 3});
  b.box({4.8, -4.8, 0}, {5, 4.8, 3});
  b.box({-5, -5, 3}, {5, 5, 3.2});
  return b.take();
}

TEST(RayCaster, HitsKnownGeometryWhereItShould) {
  const RayCaster caster(room());
  const Eigen::Vector3f o(0, 0, 1);
  EXPECT_NEAR(caster.cast(o, Eigen::Vector3f::UnitX(), 0, 100), 4.8f, 1e-4);
  EXPECT_NEAR(caster.cast(o, -Eigen::Vector3f::UnitY(), 0, 100), 4.8f, 1e-4);
  EXPECT_NEAR(caster.cast(o, -Eigen::Vector3f::UnitZ(), 0, 100), 1.0f, 1e-4);
  EXPECT_NEAR(caster.cast(o, Eigen::Vector3f::UnitZ(), 0, 100), 2.0f, 1e-4);
  EXPECT_EQ(caster.cast(o, Eigen::Vector3f::UnitX(), 0, 4.0f), RayCaster::kMiss);  // beyond t_far
  // Two-sided: from outside, the wall's outer face is hit too.
  EXPECT_NEAR(caster.cast({10, 0, 1}, -Eigen::Vector3f::UnitX(), 0, 100), 5.0f, 1e-4);
  EXPECT_TRUE(caster.occluded(o, Eigen::Vector3f::UnitX(), 0, 10));
  EXPECT_FALSE(caster.occluded(o, Eigen::Vector3f::UnitX(), 0, 4));
  EXPECT_EQ(caster.cast({0, 0, 10}, Eigen::Vector3f::UnitZ(), 0, 100), RayCaster::kMiss);
}

TEST(RayCaster, FanMatchesSingleRays) {
  const RayCaster caster(room());
  std::vector<Eigen::Vector3f> dirs;
  for (int i = 0; i < 37; ++i) {
    const float a = 0.17f * i;
    dirs.push_back(Eigen::Vector3f(std::cos(a), std::sin(a), 0.3f * std::sin(3.0f * a)).normalized());
  }
  std::vector<float> out(dirs.size());
  const Eigen::Vector3f o(1, -2, 1.5);
  caster.cast_fan(o, dirs, 0, 50, out);
  for (size_t i = 0; i < dirs.size(); ++i) EXPECT_NEAR(out[i], caster.cast(o, dirs[i], 0, 50), 1e-5) << i;
}

TEST(RayCaster, EmptyMeshIsRejected) { EXPECT_THROW(RayCaster(TriangleMesh{}), SceneError); }

TEST(ProxyBox, RayAndOverlapTests) {
  ProxyBox box;
  box.center = {5, 0, 0.5};
  box.half_extents = {0.5, 0.5, 0.5};
  box.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(intersect_box(box, {0, 0, 0.5}, Eigen::Vector3d::UnitX(), 0, 100), 5.0 - 0.5 * std::sqrt(2.0), 1e-9);
  EXPECT_TRUE(std::isinf(intersect_box(box, {0, 0, 0.5}, Eigen::Vector3d::UnitY(), 0, 100)));
  ProxyBox other = box;
  other.center.x() += 1.2;  // the rotated boxes reach 0.707 m along x each
  EXPECT_TRUE(boxes_overlap(box, other));
  other.center.x() += 0.3;
  EXPECT_FALSE(boxes_overlap(box, other));
}

}  // namespace
}  // namespace hexplore::sim
