#include "common/safety/box_detour.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexplore::safety {
namespace {

constexpr double kEps = 1e-6;

// Moves the face of least penetration just past `p`, so p ends up outside the box.
void shrink_to_exclude(ObstacleBox& box, const Eigen::Vector2d& p) {
  const double pen[4] = {p.x() - box.min_m.x(), box.max_m.x() - p.x(), p.y() - box.min_m.y(), box.max_m.y() - p.y()};
  const int side = static_cast<int>(std::min_element(pen, pen + 4) - pen);
  const double gap = 1e-3;
  switch (side) {
    case 0: box.min_m.x() = p.x() + gap; break;
    case 1: box.max_m.x() = p.x() - gap; break;
    case 2: box.min_m.y() = p.y() + gap; break;
    default: box.max_m.y() = p.y() - gap; break;
  }
}

bool any_contains(const std::vector<ObstacleBox>& boxes, const Eigen::Vector2d& p, size_t* which = nullptr) {
  for (size_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i].contains(p)) {
      if (which) *which = i;
      return true;
    }
  }
  return false;
}

bool segment_free(const std::vector<ObstacleBox>& boxes, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  for (const auto& box : boxes) {
    if (box.intersects_segment(a, b)) return false;
  }
  return true;
}

// Shortest corner-to-corner route from `from` to `to` among the boxes (visibility graph).
bool shortest_route(const std::vector<ObstacleBox>& boxes, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                    double clearance, std::vector<Eigen::Vector2d>& route) {
  std::vector<Eigen::Vector2d> nodes{from, to};
  for (const auto& box : boxes) {
    const Eigen::Vector2d lo = box.min_m.array() - clearance;
    const Eigen::Vector2d hi = box.max_m.array() + clearance;
    for (const Eigen::Vector2d& c :
         {Eigen::Vector2d(lo.x(), lo.y()), Eigen::Vector2d(hi.x(), lo.y()), Eigen::Vector2d(hi.x(), hi.y()),
          Eigen::Vector2d(lo.x(), hi.y())}) {
      if (!any_contains(boxes, c)) nodes.push_back(c);
    }
  }
  const size_t n = nodes.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> prev(n, -1);
  std::vector<bool> done(n, false);
  dist[0] = 0.0;
  // Dense Dijkstra: a handful of boxes gives a few dozen nodes; index order breaks ties.
  for (size_t iter = 0; iter < n; ++iter) {
    int u = -1;
    for (size_t i = 0; i < n; ++i) {
      if (!done[i] && std::isfinite(dist[i]) && (u < 0 || dist[i] < dist[u] - 1e-12)) u = static_cast<int>(i);
    }
    if (u < 0 || u == 1) break;
    done[u] = true;
    for (size_t v = 0; v < n; ++v) {
      if (done[v] || static_cast<int>(v) == u) continue;
      const double w = (nodes[v] - nodes[u]).norm();
      if (dist[u] + w < dist[v] - 1e-12 && segment_free(boxes, nodes[u], nodes[v])) {
        dist[v] = dist[u] + w;
        prev[v] = u;
      }
    }
  }
  if (!std::isfinite(dist[1])) return false;
  route.clear();
  for (int v = prev[1]; v > 0; v = prev[v]) route.push_back(nodes[v]);
  std::reverse(route.begin(), route.end());
  return true;
}

}  // namespace

bool ObstacleBox::contains(const Eigen::Vector2d& p) const {
  return p.x() > min_m.x() + kEps && p.x() < max_m.x() - kEps && p.y() > min_m.y() + kEps && p.y() < max_m.y() - kEps;
}

bool ObstacleBox::intersects_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  // Liang-Barsky clipping against the box shrunk by kEps: a positive-length overlap means the
  // segment crosses the interior.
  const Eigen::Vector2d lo = min_m.array() + kEps;
  const Eigen::Vector2d hi = max_m.array() - kEps;
  if ((hi.array() <= lo.array()).any()) return false;
  const Eigen::Vector2d d = b - a;
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-12) {
      if (a[axis] <= lo[axis] || a[axis] >= hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - a[axis]) / d[axis];
    double tb = (hi[axis] - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 >= t1) return false;
  }
  return t1 - t0 > 1e-9;
}

DetourResult detour_around(const Path& input, std::vector<ObstacleBox> boxes, const DetourOptions& options) {
  DetourResult result;
  result.path = input;
  if (input.size() < 2 || boxes.empty()) return result;
  const Eigen::Vector2d start = input.front().head<2>();
  for (auto& box : boxes) {
    if (box.contains(start)) shrink_to_exclude(box, start);
  }

  Path path = input;
  double resume_s = 0.0;  // everything before this arc length is already free
  for (int round = 0; round < options.max_detours; ++round) {
    const auto samples = sample_path(path, options.sample_step_m);
    size_t entry = samples.size();
    size_t box_index = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
      if (samples[i].s_m < resume_s) continue;
      if (any_contains(boxes, samples[i].point.head<2>(), &box_index)) {
        entry = i;
        break;
      }
      // Thin boxes can sit between two samples: test the connecting piece too.
      if (i > 0 && samples[i - 1].s_m >= resume_s) {
        bool hit = false;
        for (size_t b = 0; b < boxes.size() && !hit; ++b) {
          if (boxes[b].intersects_segment(samples[i - 1].point.head<2>(), samples[i].point.head<2>())) {
            hit = true;
            box_index = b;
          }
        }
        if (hit) {
          entry = i;
          break;
        }
      }
    }
    if (entry == samples.size()) {
      result.path = path;
      return result;
    }
    size_t before = entry == 0 ? 0 : entry - 1;
    // A detour that starts just ahead of the robot starts at the robot instead: otherwise a
    // route that turns back would make the robot step forward and back on the spot.
    if (samples[before].s_m <= options.start_snap_m && resume_s == 0.0) before = 0;
    size_t exit = entry;
    while (exit < samples.size() && any_contains(boxes, samples[exit].point.head<2>())) ++exit;
    std::vector<Eigen::Vector2d> route;
    // The last round may not splice any more: cutting short keeps the result collision-free.
    const bool reachable = round + 1 < options.max_detours && exit < samples.size() &&
                           shortest_route(boxes, samples[before].point.head<2>(), samples[exit].point.head<2>(),
                                          options.clearance_m, route);
    if (reachable && before > 0 && resume_s == 0.0 && !route.empty()) {
      // A route that turns back at its start is better begun at the robot (no U-turn).
      const Eigen::Vector2d ahead = direction_at(path, samples[before].s_m).head<2>();
      std::vector<Eigen::Vector2d> from_start;
      if (ahead.dot(route.front() - samples[before].point.head<2>()) < 0.0 &&
          shortest_route(boxes, samples[0].point.head<2>(), samples[exit].point.head<2>(), options.clearance_m,
                         from_start)) {
        before = 0;
        route = std::move(from_start);
      }
    }
    if (!reachable) {
      result.blocked = true;
      result.blocked_by = boxes[box_index].robot_id;
      result.path = truncate_to_length(path, samples[before].s_m);
      return result;
    }
    // Splice: path up to the last free sample, the corner route, then the path from the exit.
    const Eigen::Vector3d p_in = samples[before].point;
    const Eigen::Vector3d p_out = samples[exit].point;
    Path spliced = truncate_to_length(path, samples[before].s_m);
    for (size_t k = 0; k < route.size(); ++k) {
      const double t = static_cast<double>(k + 1) / static_cast<double>(route.size() + 1);
      spliced.emplace_back(route[k].x(), route[k].y(), p_in.z() + t * (p_out.z() - p_in.z()));
    }
    const double splice_end_s = path_length(spliced) + distance_xy(spliced.back(), p_out);
    spliced.push_back(p_out);
    double travelled = 0.0;
    for (size_t i = 1; i < path.size(); ++i) {
      travelled += distance_xy(path[i - 1], path[i]);
      if (travelled > samples[exit].s_m + 1e-9 && distance_xy(path[i], spliced.back()) > 1e-9) spliced.push_back(path[i]);
    }
    path = std::move(spliced);
    resume_s = splice_end_s;
    result.detoured = true;
  }
  result.path = path;
  return result;
}

}  // namespace hexplore::safety
