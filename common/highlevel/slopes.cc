#include "common/highlevel/slopes.h"

#include <algorithm>
#include <cmath>

#include "common/highlevel/clearance.h"

namespace hexplore::highlevel {
namespace {

// A flight's pieces seen from below (B1's flight of the multi-building scene, stop 58): centres
// 0.03-0.04 m off each other's planes, normals within 2 deg. A step between two floors or a
// kerb is far off either plane (its normals are vertical anyway).
constexpr double kPlaneToleranceM = 0.15;
constexpr double kNormalToleranceDeg = 10.0;
// Risers of B1's flight (stop 58): centres 0.01-0.04 m off the plane of the ground beside them;
// treads seen too steeply to be ground, up to 0.05 m.
constexpr double kStepToleranceM = 0.25;

double tilt_deg(const Eigen::Vector3d& normal) {
  return std::acos(std::clamp(normal.z(), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

bool sloped(const Supervoxel& ground) { return ground.ground() && tilt_deg(ground.normal) >= kSlopeTiltDeg; }

bool step_of_slope(const Eigen::Vector3d& ground_center, const Eigen::Vector3d& ground_normal,
                   const Eigen::Vector3d& facade_center, const Eigen::Vector3d& facade_normal) {
  if (tilt_deg(ground_normal) < kSlopeTiltDeg) return false;
  if (std::abs(ground_normal.dot(facade_center - ground_center)) > kStepToleranceM) return false;
  const Eigen::Vector2d downhill = ground_normal.head<2>().normalized();
  const Eigen::Vector3d across(-downhill.y(), downhill.x(), 0.0);
  return std::abs(facade_normal.dot(across)) < 0.5;
}

uint8_t uphill_sides(const Supervoxel& ground, uint8_t sides) {
  if (sides == 0 || !sloped(ground)) return 0;
  const Eigen::Vector2d uphill = -ground.normal.head<2>().normalized();
  uint8_t out = 0;
  for (int i = 0; i < kRimSideCount; ++i)
    if ((sides & (1u << i)) && rim_side_direction(i).dot(uphill) >= std::cos(M_PI / 4) - 1e-9) out |= uint8_t(1u << i);
  return out;
}

bool on_one_slope(const Supervoxel& a, const Supervoxel& b, double reach_m) {
  if (!sloped(a) || !sloped(b)) return false;
  const Eigen::Vector3d d = b.center - a.center;
  if (d.head<2>().norm() > reach_m) return false;
  if (a.normal.dot(b.normal) < std::cos(kNormalToleranceDeg * M_PI / 180.0)) return false;
  return std::abs(a.normal.dot(d)) <= kPlaneToleranceM && std::abs(b.normal.dot(d)) <= kPlaneToleranceM;
}

}  // namespace hexplore::highlevel
