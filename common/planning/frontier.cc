#include "common/planning/frontier.h"

#include "common/highlevel/clearance.h"

namespace hexplore::planning {

bool at_frontier(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& sv, const Eigen::AlignedBox3d& region) {
  if (!sv.traversable()) return false;
  const uint8_t open = map.frontier_sides(sv.key);
  if (open == 0) return false;
  const double step = map.clearance_options().ground_spacing_m;
  for (int i = 0; i < highlevel::kRimSideCount; ++i) {
    if ((open & (1u << i)) == 0) continue;
    Eigen::Vector3d beyond = sv.center;
    beyond.head<2>() += step * highlevel::rim_side_direction(i);
    if (region.contains(beyond)) return true;
  }
  return false;
}

bool needs_look(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& sv, const Eigen::AlignedBox3d& region) {
  return !sv.covered || at_frontier(map, sv, region);
}

}  // namespace hexplore::planning
