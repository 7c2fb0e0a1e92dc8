#include "common/sim/lidar.h"

#include <algorithm>
#include <cmath>

#include "common/core/rng.h"

namespace hexplore::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr size_t kNoiseTable = 1 << 16;

}  // namespace

LidarModel::LidarModel(core::LidarConfig config, uint64_t seed) : config_(std::move(config)), noise_state_(seed) {
  const int lines = std::max(1, config_.lines);
  const int columns = std::max(1, config_.rays_per_frame() / lines);
  const double span = config_.horizontal_max_deg - config_.horizontal_min_deg;
  dirs_.reserve(static_cast<size_t>(lines) * columns);
  // Column-major: the 16-ray packets then share one azimuth, which keeps them coherent.
  for (int c = 0; c < columns; ++c) {
    const double az = (config_.horizontal_min_deg + (c + 0.5) * span / columns) * kDeg;
    for (int l = 0; l < lines; ++l) {
      const double el_deg = lines == 1 ? 0.5 * (config_.vertical_min_deg + config_.vertical_max_deg)
                                       : config_.vertical_min_deg +
                                             l * (config_.vertical_max_deg - config_.vertical_min_deg) / (lines - 1);
      const double el = el_deg * kDeg;
      dirs_.emplace_back(static_cast<float>(std::cos(el) * std::cos(az)), static_cast<float>(std::cos(el) * std::sin(az)),
                         static_cast<float>(std::sin(el)));
    }
  }
  core::SimRng rng(core::sim_seed(seed, 0x1D4A));
  noise_.resize(kNoiseTable);
  for (auto& n : noise_) n = static_cast<float>(rng.normal());
  world_dirs_.resize(dirs_.size());
  ranges_.resize(dirs_.size());
}

void LidarModel::set_gimbal(double yaw_rad, double pitch_rad) {
  if (!config_.gimbal) return;
  gimbal_yaw_ = yaw_rad;
  gimbal_pitch_ = std::clamp(pitch_rad, -M_PI / 2, M_PI / 2);
}

Eigen::Isometry3d LidarModel::mount_pose() const {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.translate(config_.mount_offset_m);
  // Positive mount pitch lifts the nose: a rotation about +y by a negative angle.
  m.rotate(Eigen::AngleAxisd(-config_.mount_pitch_deg * kDeg, Eigen::Vector3d::UnitY()));
  return m;
}

void LidarModel::aim_at(const Eigen::Vector3d& target_world, const Eigen::Isometry3d& body_pose) {
  if (!config_.gimbal) return;
  const Eigen::Vector3d p = (body_pose * mount_pose()).inverse() * target_world;
  if (p.norm() < 1e-6) return;
  set_gimbal(std::atan2(p.y(), p.x()), std::atan2(p.z(), std::hypot(p.x(), p.y())));
}

Eigen::Isometry3d LidarModel::sensor_pose(const Eigen::Isometry3d& body_pose) const {
  Eigen::Isometry3d s = body_pose * mount_pose();
  if (config_.gimbal) {
    s.rotate(Eigen::AngleAxisd(gimbal_yaw_, Eigen::Vector3d::UnitZ()));
    s.rotate(Eigen::AngleAxisd(-gimbal_pitch_, Eigen::Vector3d::UnitY()));
  }
  return s;
}

LidarScan LidarModel::scan(const RayCaster& caster, const Eigen::Isometry3d& body_pose,
                           std::span<const ProxyBox> proxies) {
  LidarScan out;
  out.sensor_name = config_.name;
  out.sensor_pose = sensor_pose(body_pose);
  out.origin = out.sensor_pose.translation();
  out.rays = dirs_.size();
  core::SimRng pick(noise_state_);
  noise_state_ = pick.next();
  Eigen::Matrix3d pattern = Eigen::Matrix3d::Identity();
  if (config_.non_repetitive) {
    // Turn the pattern by up to one column step in azimuth and half a line spacing in tilt
    // (about both horizontal axes, so the elevation shift varies with azimuth).
    const int lines = std::max(1, config_.lines);
    const double spacing = lines > 1 ? (config_.vertical_max_deg - config_.vertical_min_deg) / (lines - 1) : 1.0;
    const double yaw = pick.uniform() * config_.horizontal_step_deg * kDeg;
    const double pitch = (pick.uniform() - 0.5) * spacing * kDeg;
    const double roll = (pick.uniform() - 0.5) * spacing * kDeg;
    pattern = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                  .toRotationMatrix();
  }
  const Eigen::Matrix3f r = (out.sensor_pose.linear() * pattern).cast<float>();
  const Eigen::Vector3f o = out.origin.cast<float>();
  for (size_t i = 0; i < dirs_.size(); ++i) world_dirs_[i] = r * dirs_[i];
  const float max_range = static_cast<float>(config_.max_range_m);
  caster.cast_fan(o, world_dirs_, 0.0f, max_range, ranges_);

  // Teammates' proxies: the origin is shared, so each box needs one transform per frame and
  // a slab test per ray.
  for (const auto& box : proxies) {
    const double reach = box.half_extents.norm();
    if ((box.center - out.origin).norm() - reach > config_.max_range_m) continue;
    const Eigen::Matrix3f rt = box.orientation.toRotationMatrix().transpose().cast<float>();
    const Eigen::Vector3f ol = rt * (o - box.center.cast<float>());
    const Eigen::Vector3f h = box.half_extents.cast<float>();
    for (size_t i = 0; i < dirs_.size(); ++i) {
      const Eigen::Vector3f d = rt * world_dirs_[i];
      float t0 = 0.0f, t1 = std::min(ranges_[i], max_range);
      bool hit = true;
      for (int a = 0; a < 3 && hit; ++a) {
        const float inv = 1.0f / d[a];  // +-inf for axis-parallel rays: the slab test still works
        float ta = (-h[a] - ol[a]) * inv, tb = (h[a] - ol[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        hit = t0 <= t1;
      }
      if (hit && t0 < ranges_[i]) ranges_[i] = t0 > 0.0f ? t0 : t1;
    }
  }

  size_t n = pick.next() % kNoiseTable;
  const float sigma = static_cast<float>(config_.range_noise_stddev_m);
  const float min_range = static_cast<float>(config_.min_range_m);
  out.points.reserve(dirs_.size());
  for (size_t i = 0; i < dirs_.size(); ++i) {
    const float t = ranges_[i];
    if (!(t <= max_range)) continue;  // no return (also catches kMiss)
    const float noisy = t + sigma * noise_[n];
    n = (n + 1) & (kNoiseTable - 1);
    if (noisy < min_range || noisy > max_range) continue;
    out.points.push_back(o + noisy * world_dirs_[i]);
  }
  return out;
}

}  // namespace hexplore::sim
