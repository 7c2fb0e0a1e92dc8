#include "common/perception/teammate_filter.h"

namespace hexplore::perception {

BodyFilter::BodyFilter(const std::vector<OrientedBox>& boxes, double margin_m) {
  for (const OrientedBox& b : boxes) {
    if (!b.centre.allFinite() || !b.half_extents_m.allFinite() || !b.orientation.coeffs().allFinite() ||
        b.orientation.norm() < 1e-9) {
      continue;
    }
    Prepared p;
    const Eigen::Matrix3d r = b.orientation.normalized().toRotationMatrix();
    p.world_to_box = r.transpose();
    p.centre = b.centre;
    p.half = b.half_extents_m.cwiseAbs() + Eigen::Vector3d::Constant(margin_m);
    const Eigen::Vector3d reach = r.cwiseAbs() * p.half;
    p.aabb_min = p.centre - reach;
    p.aabb_max = p.centre + reach;
    boxes_.push_back(p);
  }
}

bool BodyFilter::contains(const Eigen::Vector3d& p) const {
  for (const Prepared& b : boxes_) {
    if ((p.array() < b.aabb_min.array()).any() || (p.array() > b.aabb_max.array()).any()) continue;
    const Eigen::Vector3d local = b.world_to_box * (p - b.centre);
    if ((local.cwiseAbs().array() <= b.half.array()).all()) return true;
  }
  return false;
}

}  // namespace hexplore::perception
