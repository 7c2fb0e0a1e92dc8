#include "common/highlevel/supervoxel.h"

#include <limits>

#include "common/core/team_config.h"
#include "common/highlevel/wire_precision.h"

namespace hexplore::highlevel {

Supervoxel wire_rounded(Supervoxel s) {
  for (int a = 0; a < 3; ++a) s.center[a] = centre_from_steps(centre_steps(s.center[a]));
  s.normal = unpack_normal(pack_normal(s.normal));
  return s;
}

std::vector<int> species_levels(const core::TeamConfig& team) {
  std::vector<int> levels;
  levels.reserve(team.species.size());
  for (const auto& s : team.species) levels.push_back(s.traversal_level);
  return levels;
}

int traversal_requirement(uint32_t all_voxels_low_risk_mask, const std::vector<int>& levels) {
  int best = std::numeric_limits<int>::max();
  for (size_t k = 0; k < levels.size() && k < 32; ++k) {
    if ((all_voxels_low_risk_mask >> k) & 1u) best = std::min(best, levels[k]);
  }
  return best == std::numeric_limits<int>::max() ? 0 : best;
}

}  // namespace hexplore::highlevel
