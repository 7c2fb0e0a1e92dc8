#pragma once
// Teammates' bodies as oriented boxes (from their latest shared poses), so that LiDAR returns
// from a teammate never enter the map as if it were terrain.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hexplore::perception {

struct OrientedBox {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
};

// A box prepared for fast point tests: inverse rotation and a world-frame bounding box.
class BodyFilter {
 public:
  // Boxes are grown by `margin_m` on every side; boxes with non-finite fields are ignored.
  BodyFilter(const std::vector<OrientedBox>& boxes, double margin_m);

  bool contains(const Eigen::Vector3d& p) const;
  bool empty() const { return boxes_.empty(); }

 private:
  struct Prepared {
    Eigen::Matrix3d world_to_box;
    Eigen::Vector3d centre;
    Eigen::Vector3d half;
    Eigen::Vector3d aabb_min;
    Eigen::Vector3d aabb_max;
  };
  std::vector<Prepared> boxes_;
};

}  // namespace hexplore::perception
