#pragma once
// Oriented boxes for bodies that are not part of the static scene: teammates' kinematic
// proxies (driven by their shared poses) and the robot's own body for contact tests.

#include <cstdint>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hexplore::sim {

struct ProxyBox {
  uint32_t id = 0;  // who it is (robot index), for contact bookkeeping
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// Distance along the unit ray to the box surface within [t_near, t_far] (the exit point
// when the origin is inside), or +infinity. Two-sided like the scene.
double intersect_box(const ProxyBox& box, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir_unit,
                     double t_near, double t_far);

// Whether two oriented boxes overlap (separating-axis test).
bool boxes_overlap(const ProxyBox& a, const ProxyBox& b);

}  // namespace hexplore::sim
