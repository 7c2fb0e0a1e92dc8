#include "common/planning/robot_vertex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hexplore::planning {

std::optional<uint64_t> robot_vertex(const highlevel::TopologyGraph& graph, const Eigen::Vector3d& p, int species) {
  const auto nearest = graph.nearest(p, species);
  if (!nearest) return nearest;
  // Probe points on two rings around the robot; each gives its nearest passable vertex.
  constexpr double kReachM = 2.0;  // candidates farther than this from the robot are not "here"
  std::vector<uint64_t> candidates{*nearest};
  for (double r : {0.75, 1.5})
    for (int i = 0; i < 8; ++i) {
      const double a = i * M_PI / 4.0;
      const auto v = graph.nearest(p + Eigen::Vector3d(r * std::cos(a), r * std::sin(a), 0.0), species);
      const auto at = v ? graph.position(*v) : std::nullopt;
      if (at && (*at - p).norm() <= kReachM) candidates.push_back(*v);
    }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  uint64_t best = *nearest;
  size_t best_size = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (uint64_t v : candidates) {
    const size_t size = graph.distances_from(v, species).size();
    const double d = (*graph.position(v) - p).norm();
    if (size > best_size || (size == best_size && d < best_d)) best = v, best_size = size, best_d = d;
  }
  return best;
}

}  // namespace hexplore::planning
