#include "common/planning/labels.h"

#include <limits>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

int task_label(int observation_requirement, int traversal_requirement, const TeamCapabilities& team,
               double beta_zeta, double beta_varsigma) {
  if (observation_requirement <= 0 || traversal_requirement <= 0) return kUnassignable;
  int best = kUnassignable;
  double best_score = std::numeric_limits<double>::infinity();
  bool all = !team.species.empty();
  for (size_t k = 0; k < team.species.size(); ++k) {
    if (!matches(observation_requirement, traversal_requirement, team.species[k])) {
      all = false;
      continue;
    }
    const double score = capability_score(team.species[k], beta_zeta, beta_varsigma);
    if (score < best_score) {
      best_score = score;
      best = int(k);
    }
  }
  return all ? kPublic : best;
}

int observation_requirement(double view_distance_m, const TeamCapabilities& team) {
  int level = 0;
  for (const auto& k : team.species)
    if (view_distance_m < k.observation_range_m && (level == 0 || k.observation_level < level)) level = k.observation_level;
  return level;
}

}  // namespace hexplore::planning
