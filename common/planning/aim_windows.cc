#include "common/planning/aim_windows.h"

#include <algorithm>
#include <cmath>

namespace hexplore::planning {
namespace {

constexpr double kPi = 3.14159265358979323846;

double wrapped(double a) {  // into (-pi, pi]
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

struct Bearing {
  double yaw = 0.0, pitch = 0.0, range = 0.0;
};

Bearing bearing(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d d = to - from;
  return {std::atan2(d.y(), d.x()), std::atan2(d.z(), d.head<2>().norm()), d.norm()};
}

}  // namespace

std::vector<AimWindow> aim_windows(const Eigen::Vector3d& from, const std::vector<AimTarget>& targets,
                                   double half_yaw_deg, double half_pitch_deg) {
  std::vector<AimWindow> windows;
  if (half_yaw_deg <= 0.0 || half_pitch_deg <= 0.0) {
    for (const AimTarget& t : targets) windows.push_back({{t.key}, t.at});
    return windows;
  }
  const double half_yaw = half_yaw_deg * kPi / 180.0, half_pitch = half_pitch_deg * kPi / 180.0;
  std::vector<Bearing> b;
  for (const AimTarget& t : targets) b.push_back(bearing(from, t.at));
  const size_t n = targets.size();
  std::vector<char> placed(n, 0);
  // A candidate window has its left edge at one target's yaw and its lower edge at another's
  // pitch, and spans twice the half-widths: every window that holds a set of targets can be
  // slid to such edges, so the candidates contain the best one.
  auto inside = [&](size_t left_edge, size_t lower_edge, size_t j) {
    const double dy = wrapped(b[j].yaw - b[left_edge].yaw), dp = b[j].pitch - b[lower_edge].pitch;
    return dy >= 0.0 && dy <= 2.0 * half_yaw && dp >= 0.0 && dp <= 2.0 * half_pitch;
  };
  std::vector<size_t> first_index;  // per window, its earliest target (the windows' order)
  for (size_t left = n; left > 0;) {
    size_t best_a = n, best_c = n, best_count = 0;
    for (size_t a = 0; a < n; ++a) {
      if (placed[a]) continue;
      for (size_t c = 0; c < n; ++c) {
        if (placed[c] || !inside(a, c, a) || !inside(a, c, c)) continue;
        size_t count = 0;
        for (size_t j = 0; j < n; ++j) count += !placed[j] && inside(a, c, j);
        if (count > best_count) best_count = count, best_a = a, best_c = c;
      }
    }
    // Aimed at the middle of what it holds: their spans fit in the window, so every member
    // lies within the half-widths of the middle.
    double yaw_hi = 0.0, pitch_lo = b[best_c].pitch, pitch_hi = pitch_lo, range = 0.0;
    AimWindow w;
    for (size_t j = 0; j < n; ++j) {
      if (placed[j] || !inside(best_a, best_c, j)) continue;
      yaw_hi = std::max(yaw_hi, wrapped(b[j].yaw - b[best_a].yaw));
      pitch_hi = std::max(pitch_hi, b[j].pitch);
      range += b[j].range;
      w.targets.push_back(targets[j].key);
      placed[j] = 1;
      if (first_index.size() == windows.size()) first_index.push_back(j);
    }
    range /= double(w.targets.size());
    const double yaw = b[best_a].yaw + 0.5 * yaw_hi, pitch = 0.5 * (pitch_lo + pitch_hi);
    w.at = from + range * Eigen::Vector3d(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
    windows.push_back(std::move(w));
    left -= best_count;
  }
  std::vector<size_t> order(windows.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t c) { return first_index[a] < first_index[c]; });
  std::vector<AimWindow> sorted;
  for (size_t i : order) sorted.push_back(std::move(windows[i]));
  return sorted;
}

}  // namespace hexplore::planning
