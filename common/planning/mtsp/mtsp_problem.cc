#include "common/planning/mtsp/mtsp_problem.h"

#include <cmath>
#include <stdexcept>

namespace hexplore::planning {

bool MtspProblem::eligible(int robot, int city) const {
  const int s = robots[size_t(robot)].species;
  const int l = label(city);
  if (l != kPublic && l != s) return false;
  if (!std::isfinite(execution_cost(s, city))) return false;
  return std::isfinite(travel_cost(s, depot(robot), city));
}

void validate(const MtspProblem& p) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("MtspProblem: " + what); };
  if (p.num_cities < 0) fail("num_cities is negative");
  if (p.num_species < 1) fail("num_species must be at least 1");
  if (p.robots.empty()) fail("no robots");
  if (!p.city_species.empty() && p.city_species.size() != size_t(p.num_cities))
    fail("city_species has " + std::to_string(p.city_species.size()) + " entries for " +
         std::to_string(p.num_cities) + " cities");
  for (size_t r = 0; r < p.robots.size(); ++r)
    if (p.robots[r].species < 0 || p.robots[r].species >= p.num_species)
      fail("robot " + std::to_string(r) + " has species " + std::to_string(p.robots[r].species) +
           " outside [0, " + std::to_string(p.num_species) + ")");
  if (p.travel.size() != 1 && p.travel.size() != size_t(p.num_species))
    fail("travel must hold 1 or num_species matrices, has " + std::to_string(p.travel.size()));
  for (size_t s = 0; s < p.travel.size(); ++s)
    if (p.travel[s].size() != p.num_nodes())
      fail("travel[" + std::to_string(s) + "] is " + std::to_string(p.travel[s].size()) + "x" +
           std::to_string(p.travel[s].size()) + ", expected " + std::to_string(p.num_nodes()) + " nodes");
  if (!p.execution.empty()) {
    if (p.execution.size() != 1 && p.execution.size() != size_t(p.num_species))
      fail("execution must hold 0, 1 or num_species vectors");
    for (size_t s = 0; s < p.execution.size(); ++s)
      if (p.execution[s].size() != size_t(p.num_cities)) fail("execution[" + std::to_string(s) + "] has wrong size");
  }
  if (!p.positions.empty() && p.positions.size() != size_t(p.num_nodes()))
    fail("positions must be empty or hold one entry per node");
  if (p.min_cities_per_robot < 0) fail("min_cities_per_robot is negative");
  if (size_t(p.min_cities_per_robot) * p.robots.size() > size_t(p.num_cities))
    fail("min_cities_per_robot * robots exceeds the number of cities");
  for (int c = 0; c < p.num_cities; ++c) {
    const int l = p.label(c);
    if (l != kPublic && (l < 0 || l >= p.num_species))
      fail("city " + std::to_string(c) + " has label " + std::to_string(l) + " outside [0, num_species)");
    bool any = false;
    for (size_t r = 0; r < p.robots.size() && !any; ++r) any = p.eligible(int(r), c);
    if (!any) fail("city " + std::to_string(c) + " cannot be served by any robot");
  }
}

double route_cost(const MtspProblem& p, int robot, const Route& route, int* infeasible) {
  const int s = p.robots[size_t(robot)].species;
  int bad = 0;
  double sum = 0.0;
  auto add = [&](double c) {
    if (std::isfinite(c)) {
      sum += c;
    } else {
      sum += kInfeasiblePenalty;
      ++bad;
    }
  };
  int prev = p.depot(robot);
  for (int c : route) {
    add(p.travel_cost(s, prev, c));
    add(p.execution_cost(s, c));
    const int l = p.label(c);
    if (l != kPublic && l != s) add(kInfinity);
    prev = c;
  }
  if (p.kind == RouteKind::kClosed && !route.empty()) add(p.travel_cost(s, prev, p.depot(robot)));
  if (infeasible) *infeasible = bad;
  return sum;
}

}  // namespace hexplore::planning
