#pragma once
// A rotating multi-line LiDAR built from core::LidarConfig: one frame casts every
// (line, column) ray from the sensor origin, with gaussian range noise from a seeded source,
// against the static scene and the teammates' proxy boxes. Optionally on a yaw/pitch gimbal
// that is aimed at a target point.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/team_config.h"
#include "common/sim/proxy_box.h"
#include "common/sim/ray_caster.h"

namespace hexplore::sim {

// One frame: world-frame points and where the sensor was.
struct LidarScan {
  std::string sensor_name;
  Eigen::Isometry3d sensor_pose = Eigen::Isometry3d::Identity();  // sensor frame -> world
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3f> points;
  size_t rays = 0;  // rays cast, returns or not
};

class LidarModel {
 public:
  // `seed` fixes the noise sequence (derive it from the team seed, robot and sensor).
  LidarModel(core::LidarConfig config, uint64_t seed);

  const core::LidarConfig& config() const { return config_; }
  size_t ray_count() const { return dirs_.size(); }

  // Gimbal angles (rad) relative to the mount; ignored unless config().gimbal.
  void set_gimbal(double yaw_rad, double pitch_rad);
  // Points the gimbal at a world point for the given body pose (no-op without a gimbal).
  void aim_at(const Eigen::Vector3d& target_world, const Eigen::Isometry3d& body_pose);
  double gimbal_yaw() const { return gimbal_yaw_; }
  double gimbal_pitch() const { return gimbal_pitch_; }

  // Sensor frame -> world for a body pose (body frame: x forward, z up, origin at body centre).
  Eigen::Isometry3d sensor_pose(const Eigen::Isometry3d& body_pose) const;

  // Casts one full frame. Not thread-safe on one model (it advances the noise sequence);
  // use one model per thread.
  LidarScan scan(const RayCaster& caster, const Eigen::Isometry3d& body_pose,
                 std::span<const ProxyBox> proxies = {});

 private:
  Eigen::Isometry3d mount_pose() const;  // mount frame (before the gimbal) in the body frame

  core::LidarConfig config_;
  std::vector<Eigen::Vector3f> dirs_;       // sensor-frame unit directions, column-major
  std::vector<float> noise_;                // unit normal samples, walked from a random start
  uint64_t noise_state_;
  double gimbal_yaw_ = 0.0;
  double gimbal_pitch_ = 0.0;
  std::vector<Eigen::Vector3f> world_dirs_;  // scratch
  std::vector<float> ranges_;                // scratch
};

}  // namespace hexplore::sim
