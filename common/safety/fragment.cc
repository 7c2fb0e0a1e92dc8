#include "common/safety/fragment.h"

#include <algorithm>

namespace hexplore::safety {

double Fragment::body_radius_m() const {
  return 0.5 * std::max(box_max_m.x() - box_min_m.x(), box_max_m.y() - box_min_m.y());
}

Path Fragment::path() const {
  Path out{position_m};
  for (const auto& w : waypoints_m) {
    if (distance_xy(w, out.back()) > 1e-9) out.push_back(w);
  }
  return out;
}

double Fragment::distance_to(const Eigen::Vector3d& p) const {
  double d = distance_xy(p, position_m);
  for (size_t i = 0; i + 1 < trail_m.size(); ++i) {
    // Distance to the segment, horizontally.
    const Eigen::Vector2d a = trail_m[i].head<2>(), b = trail_m[i + 1].head<2>(), q = p.head<2>();
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 1e-18 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    d = std::min(d, (a + t * ab - q).norm());
  }
  return d;
}

double body_radius_of(const Eigen::Vector3d& half_extents_m) { return half_extents_m.head<2>().norm(); }

void body_box_any_yaw(const Eigen::Vector3d& p, const Eigen::Vector3d& half_extents_m, Eigen::Vector3d& box_min,
                      Eigen::Vector3d& box_max) {
  const double r = body_radius_of(half_extents_m);
  const Eigen::Vector3d h(r, r, half_extents_m.z());
  box_min = p - h;
  box_max = p + h;
}

}  // namespace hexplore::safety
