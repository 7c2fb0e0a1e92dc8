#include "common/sim/lidar.h"

#include <cmath>

#include <gtest/gtest.h>

#include "common/sim/mesh_builder.h"

namespace hexplore::sim {
namespace {

// Ground plane and a wall 10 m ahead (x = 10).
TriangleMesh wall_scene() {
  MeshBuilder b;
  b.plane(-50, -50, 50, 50, 0.0);
  b.box({10, -30, 0}, {10.5, 30, 20});
  return b.take();
}

TEST(Lidar, BuiltinModelsHaveThePapersRayCounts) {
  EXPECT_EQ(LidarModel(core::builtin_slugcat().lidars[0], 1).ray_count(), 216000u);
  const auto mr = core::builtin_mr1000();
  EXPECT_EQ(LidarModel(mr.lidars[0], 1).ray_count(), 32u * 900u);
  EXPECT_EQ(LidarModel(mr.lidars[1], 1).ray_count(), 80u * 720u);
}

TEST(Lidar, PointsLieOnTheGeometryWithinNoise) {
  const TriangleMesh mesh = wall_scene();
  const RayCaster caster(mesh);
  core::LidarConfig cfg;
  cfg.name = "test";
  cfg.lines = 16;
  cfg.horizontal_step_deg = 1.0;
  cfg.range_noise_stddev_m = 0.02;
  cfg.mount_offset_m = {0, 0, 1.0};
  LidarModel lidar(cfg, 42);
  const LidarScan scan = lidar.scan(caster, Eigen::Isometry3d::Identity());
  EXPECT_EQ(scan.rays, 16u * 360u);
  EXPECT_NEAR(scan.origin.z(), 1.0, 1e-9);
  ASSERT_GT(scan.points.size(), 1000u);
  size_t on_wall = 0, on_ground = 0;
  for (const auto& p : scan.points) {
    const double range = (p.cast<double>() - scan.origin).norm();
    EXPECT_LE(range, cfg.max_range_m + 1e-3);
    EXPECT_GE(range, cfg.min_range_m - 1e-3);
    // Every point is on the wall's face or the ground, within 5 sigma of range noise.
    const bool wall = std::abs(p.x() - 10.0) < 0.1, ground = std::abs(p.z()) < 0.1;
    on_wall += wall;
    on_ground += ground;
    EXPECT_TRUE(wall || ground) << p.transpose();
  }
  EXPECT_GT(on_wall, 100u);
  EXPECT_GT(on_ground, 100u);
  // The horizontal line straight ahead hits the wall at 10 m (range noise 2 cm).
  Eigen::Vector3f best(0, 0, 0);
  double best_err = 1e9;
  for (const auto& p : scan.points)
    if (std::abs(p.y()) < 0.2 && std::abs(p.z() - 1.0) < 0.2 && std::abs(p.x() - 10.0) < best_err) {
      best_err = std::abs(p.x() - 10.0);
      best = p;
    }
  EXPECT_LT(best_err, 0.1);
}

TEST(Lidar, NoiseIsDeterministicPerSeed) {
  const TriangleMesh mesh = wall_scene();
  const RayCaster caster(mesh);
  auto cfg = core::builtin_mr1000().lidars[1];
  LidarModel a(cfg, 5), b(cfg, 5), c(cfg, 6);
  const auto sa = a.scan(caster, Eigen::Isometry3d::Identity());
  const auto sb = b.scan(caster, Eigen::Isometry3d::Identity());
  const auto sc = c.scan(caster, Eigen::Isometry3d::Identity());
  ASSERT_EQ(sa.points.size(), sb.points.size());
  EXPECT_TRUE(sa.points == sb.points);
  EXPECT_FALSE(sa.points == sc.points);
}

TEST(Lidar, TeammateProxiesAreHit) {
  const TriangleMesh mesh = wall_scene();
  const RayCaster caster(mesh);
  core::LidarConfig cfg;
  cfg.lines = 8;
  cfg.horizontal_step_deg = 0.5;
  cfg.range_noise_stddev_m = 0.0;
  cfg.mount_offset_m = {0, 0, 0.5};
  LidarModel lidar(cfg, 1);
  ProxyBox mate;
  mate.center = {3, 0, 0.5};
  mate.half_extents = {0.5, 0.4, 0.5};
  const std::vector<ProxyBox> proxies = {mate};
  const auto scan = lidar.scan(caster, Eigen::Isometry3d::Identity(), proxies);
  size_t on_box = 0;
  for (const auto& p : scan.points)
    if (std::abs(p.x() - 2.5) < 1e-3 && std::abs(p.y()) <= 0.4 + 1e-3) ++on_box;
  EXPECT_GT(on_box, 10u);
  for (const auto& p : scan.points)  // nothing behind the box on its axis
    EXPECT_FALSE(std::abs(p.y()) < 0.3 && std::abs(p.z() - 0.5) < 0.3 && p.x() > 2.6) << p.transpose();
}

TEST(Lidar, GimbalAimsTheNarrowSensorAtATarget) {
  const TriangleMesh mesh = wall_scene();
  const RayCaster caster(mesh);
  auto cfg = core::builtin_mr1000().lidars[0];  // +-45 x +-11.25 deg, gimballed
  cfg.range_noise_stddev_m = 0.0;
  LidarModel lidar(cfg, 3);
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  body.rotate(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()));  // facing away from the wall
  for (const auto& p : lidar.scan(caster, body).points) ASSERT_LT(p.x(), 9.0);  // the wall is behind it
  const Eigen::Vector3d target(10, 0, 15);                            // high up on the wall
  lidar.aim_at(target, body);
  const auto scan = lidar.scan(caster, body);
  ASSERT_GT(scan.points.size(), 1000u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : scan.points) mean += p.cast<double>();
  mean /= static_cast<double>(scan.points.size());
  EXPECT_NEAR(mean.x(), 10.0, 0.05);
  EXPECT_NEAR(mean.z(), 15.0, 2.0);
}

}  // namespace
}  // namespace hexplore::sim
