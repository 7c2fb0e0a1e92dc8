#pragma once
// TSPGA+'s allocation (BASELINES.md; after Hardouin et al., T-RO 2023): task clusters go
// one at a time to robots by greedy information-gain utility. A robot's utility is
//   U(route) = sum over its clusters c of gain(c) * exp(-lambda * t_c),
// t_c = when it finishes c (travel from its depot plus execution, in seconds). Each step
// inserts, among every unassigned cluster and every robot that may serve it, the pair whose
// insertion at the robot's cheapest position (least added time) raises that robot's utility
// most; then each route's order is improved by 2-opt on its cost. Deterministic.

#include <vector>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

double route_utility(const MtspProblem& problem, int robot, const Route& route, const std::vector<double>& gain,
                     double lambda);

struct GreedyInsertion {
  int robot = -1;  // -1: no unassigned city can be placed
  int city = -1;
  int position = -1;  // index in the robot's route the city takes
  double increment = 0.0;
};

// The next step of the greedy. Ties: lower robot, then lower city (cities are in cluster-id order).
GreedyInsertion best_insertion(const MtspProblem& problem, const std::vector<Route>& routes,
                               const std::vector<char>& assigned, const std::vector<double>& gain, double lambda);

// Greedy allocation of every city some robot may serve, then 2-opt of each route.
std::vector<Route> greedy_allocation(const MtspProblem& problem, const std::vector<double>& gain, double lambda);

// 2-opt of one open route's order on route_cost (first improvement until none helps).
void two_opt_route(const MtspProblem& problem, int robot, Route& route);

}  // namespace hexplore::planning
