#pragma once
// Task labels (paper eq. matchFunc, capability score, eq. 4-11): a view is public when every
// species can take it, else private to the matching species with the lowest capability
// score, so strong robots are not overloaded. Matching reads "requirement <= capability".

#include <vector>

#include "common/planning/capabilities.h"

namespace hexplore::planning {

inline constexpr int kUnassignable = -2;  // no species matches (kPublic = -1, else species index)

// I(xi, k): the species meets both requirements.
inline bool matches(int observation_requirement, int traversal_requirement, const SpeciesCapability& k) {
  return observation_requirement <= k.observation_level && traversal_requirement <= k.traversal_level;
}

// a(k) = beta_zeta * a_zeta(k) + beta_varsigma * a_varsigma(k).
inline double capability_score(const SpeciesCapability& k, double beta_zeta, double beta_varsigma) {
  return beta_zeta * k.traversal_level + beta_varsigma * k.observation_level;
}

// c(xi): kPublic, the index of the weakest matching species (ties: lower index), or
// kUnassignable.
int task_label(int observation_requirement, int traversal_requirement, const TeamCapabilities& team,
               double beta_zeta, double beta_varsigma);

// Observation requirement (eq. observationRequirement): the lowest observation level among
// species whose range exceeds the view distance; 0 when no species reaches that far.
int observation_requirement(double view_distance_m, const TeamCapabilities& team);

}  // namespace hexplore::planning
