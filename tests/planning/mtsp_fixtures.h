#pragma once
// Small random Euclidean HMDMTSP instances for the planning tests.

#include <cmath>
#include <vector>

#include "common/planning/mtsp/mtsp_problem.h"
#include "common/core/rng.h"

namespace hexplore::planning::testing {

// Cities and one depot per robot uniformly in a 100 x 100 square; robot r has species
// robot_species[r]; city labels drawn from {public, 0..num_species-1} when `labelled`.
inline MtspProblem random_problem(int cities, const std::vector<int>& robot_species, int num_species, RouteKind kind,
                                  uint64_t seed, bool labelled = false) {
  core::PlanRng rng(seed);
  MtspProblem p;
  p.num_cities = cities;
  p.num_species = num_species;
  p.kind = kind;
  for (int s : robot_species) p.robots.push_back({s});
  p.positions.resize(size_t(p.num_nodes()));
  for (auto& x : p.positions) x = {100.0 * rng.uniform(), 100.0 * rng.uniform(), 0.0};
  if (labelled) {
    p.city_species.resize(size_t(cities));
    for (auto& l : p.city_species) l = int(rng.below(uint64_t(num_species) + 1)) - 1;
  }
  CostMatrix m(p.num_nodes());
  for (int a = 0; a < p.num_nodes(); ++a)
    for (int b = 0; b < p.num_nodes(); ++b) m.set(a, b, (p.positions[size_t(a)] - p.positions[size_t(b)]).norm());
  p.travel.push_back(std::move(m));
  return p;
}

}  // namespace hexplore::planning::testing
