#include "common/sim/proxy_box.h"

#include <algorithm>
#include <cmath>

namespace hexplore::sim {

double intersect_box(const ProxyBox& box, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir_unit,
                     double t_near, double t_far) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Eigen::Matrix3d rt = box.orientation.toRotationMatrix().transpose();
  const Eigen::Vector3d o = rt * (origin - box.center), d = rt * dir_unit;
  double t0 = -kInf, t1 = kInf;
  for (int a = 0; a < 3; ++a) {
    const double h = box.half_extents[a];
    if (std::abs(d[a]) < 1e-12) {
      if (o[a] < -h || o[a] > h) return kInf;
      continue;
    }
    double ta = (-h - o[a]) / d[a], tb = (h - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kInf;
  }
  if (t0 >= t_near && t0 <= t_far) return t0;
  if (t1 >= t_near && t1 <= t_far) return t1;  // origin inside: the far face is hit
  return kInf;
}

bool boxes_overlap(const ProxyBox& a, const ProxyBox& b) {
  const Eigen::Matrix3d ra = a.orientation.toRotationMatrix(), rb = b.orientation.toRotationMatrix();
  const Eigen::Vector3d t = b.center - a.center;
  Eigen::Vector3d axes[15];
  int n = 0;
  for (int i = 0; i < 3; ++i) axes[n++] = ra.col(i);
  for (int i = 0; i < 3; ++i) axes[n++] = rb.col(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d c = ra.col(i).cross(rb.col(j));
      if (c.squaredNorm() > 1e-12) axes[n++] = c.normalized();
    }
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d& l = axes[k];
    double pa = 0, pb = 0;
    for (int i = 0; i < 3; ++i) {
      pa += a.half_extents[i] * std::abs(ra.col(i).dot(l));
      pb += b.half_extents[i] * std::abs(rb.col(i).dot(l));
    }
    if (std::abs(t.dot(l)) > pa + pb) return false;
  }
  return true;
}

}  // namespace hexplore::sim
