#include "common/safety/polyline.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexplore::safety {

double distance_xy(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).head<2>().norm(); }

double path_length(const Path& path) {
  double total = 0.0;
  for (size_t i = 1; i < path.size(); ++i) total += distance_xy(path[i - 1], path[i]);
  return total;
}

Path remaining_path(const Eigen::Vector3d& position, const Path& waypoints) {
  return remaining_path(position, waypoints, 0.0, std::numeric_limits<double>::infinity(), nullptr);
}

Path remaining_path(const Eigen::Vector3d& position, const Path& waypoints, double from_s, double to_s, double* at_s) {
  if (at_s) *at_s = 0.0;
  if (waypoints.empty()) return {position};
  if (waypoints.size() == 1) return {position, waypoints.front()};
  double best = std::numeric_limits<double>::infinity();
  size_t best_segment = 0;
  Eigen::Vector3d best_point = waypoints.front();
  double best_s = 0.0;
  double start_s = 0.0;
  for (size_t i = 0; i + 1 < waypoints.size(); ++i) {
    const Eigen::Vector3d& a = waypoints[i];
    const Eigen::Vector3d& b = waypoints[i + 1];
    const double seg = distance_xy(a, b);
    const double end_s = start_s + seg;
    if (end_s >= from_s && start_s <= to_s) {
      const Eigen::Vector2d ab = (b - a).head<2>();
      const double len2 = ab.squaredNorm();
      double t = len2 > 0.0 ? (position - a).head<2>().dot(ab) / len2 : 0.0;
      // Only the part of the segment inside the window counts.
      const double t_min = seg > 0.0 ? std::clamp((from_s - start_s) / seg, 0.0, 1.0) : 0.0;
      const double t_max = seg > 0.0 ? std::clamp((to_s - start_s) / seg, 0.0, 1.0) : 1.0;
      t = std::clamp(t, t_min, t_max);
      const Eigen::Vector3d p = a + t * (b - a);
      const double d = distance_xy(p, position);
      // A strictly-better test keeps the earliest segment on ties (paths that revisit a point).
      if (d < best - 1e-9) {
        best = d;
        best_segment = i;
        best_point = p;
        best_s = start_s + t * seg;
      }
    }
    start_s = end_s;
  }
  if (at_s) *at_s = best_s;
  Path out{position};
  if (distance_xy(best_point, position) > 1e-6) out.push_back(best_point);
  for (size_t i = best_segment + 1; i < waypoints.size(); ++i) {
    if (distance_xy(waypoints[i], out.back()) > 1e-9) out.push_back(waypoints[i]);
  }
  return out;
}

Path truncate_to_length(const Path& path, double max_length_m) {
  if (path.empty()) return path;
  Path out{path.front()};
  double travelled = 0.0;
  const double limit = std::max(0.0, max_length_m);
  for (size_t i = 1; i < path.size(); ++i) {
    const double seg = distance_xy(path[i - 1], path[i]);
    if (travelled + seg >= limit) {
      const double t = seg > 0.0 ? (limit - travelled) / seg : 0.0;
      const Eigen::Vector3d end = path[i - 1] + t * (path[i] - path[i - 1]);
      if (distance_xy(end, out.back()) > 1e-9) out.push_back(end);
      return out;
    }
    travelled += seg;
    out.push_back(path[i]);
  }
  return out;
}

Eigen::Vector3d point_at(const Path& path, double s_m) {
  if (path.empty()) return Eigen::Vector3d::Zero();
  double travelled = 0.0;
  for (size_t i = 1; i < path.size(); ++i) {
    const double seg = distance_xy(path[i - 1], path[i]);
    if (travelled + seg >= s_m) {
      const double t = seg > 0.0 ? std::max(0.0, s_m - travelled) / seg : 0.0;
      return path[i - 1] + t * (path[i] - path[i - 1]);
    }
    travelled += seg;
  }
  return path.back();
}

Eigen::Vector3d direction_at(const Path& path, double s_m) {
  double travelled = 0.0;
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  for (size_t i = 1; i < path.size(); ++i) {
    Eigen::Vector3d d = path[i] - path[i - 1];
    d.z() = 0.0;
    const double seg = d.norm();
    if (seg <= 1e-9) continue;
    last = d / seg;
    if (travelled + seg >= s_m) return last;
    travelled += seg;
  }
  return last;
}

std::vector<PathSample> sample_path(const Path& path, double step_m) {
  std::vector<PathSample> out;
  if (path.empty()) return out;
  const double total = path_length(path);
  const double step = step_m > 1e-6 ? step_m : 0.1;
  const int count = static_cast<int>(std::floor(total / step));
  out.reserve(count + 2);
  for (int k = 0; k <= count; ++k) out.push_back({point_at(path, k * step), k * step});
  if (out.empty() || total - out.back().s_m > 1e-6) out.push_back({path.back(), total});
  return out;
}

Path extend_path(const Path& path, double extra_m) {
  if (path.size() < 2 || extra_m <= 0.0) return path;
  Eigen::Vector3d dir = path.back() - path[path.size() - 2];
  dir.z() = 0.0;
  const double n = dir.norm();
  if (n <= 1e-9) return path;
  Path out = path;
  out.push_back(path.back() + dir / n * extra_m);
  return out;
}

}  // namespace hexplore::safety
