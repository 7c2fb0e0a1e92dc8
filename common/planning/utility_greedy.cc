#include "common/planning/utility_greedy.h"

#include <algorithm>
#include <cmath>

namespace hexplore::planning {

double route_utility(const MtspProblem& p, int robot, const Route& route, const std::vector<double>& gain,
                     double lambda) {
  const int s = p.robots[size_t(robot)].species;
  double t = 0.0, u = 0.0;
  int prev = p.depot(robot);
  for (int c : route) {
    t += p.travel_cost(s, prev, c) + p.execution_cost(s, c);
    u += gain[size_t(c)] * std::exp(-lambda * t);
    prev = c;
  }
  return u;
}

GreedyInsertion best_insertion(const MtspProblem& p, const std::vector<Route>& routes, const std::vector<char>& assigned,
                               const std::vector<double>& gain, double lambda) {
  GreedyInsertion best;
  std::vector<double> finish, later;  // per position: finish time, utility of the cities from there on
  for (int r = 0; r < int(routes.size()); ++r) {
    const Route& route = routes[size_t(r)];
    const int s = p.robots[size_t(r)].species;
    const size_t m = route.size();
    finish.assign(m + 1, 0.0);  // finish[i]: when the robot is done with the first i cities
    for (size_t i = 0; i < m; ++i) {
      const int prev = i == 0 ? p.depot(r) : route[i - 1];
      finish[i + 1] = finish[i] + p.travel_cost(s, prev, route[i]) + p.execution_cost(s, route[i]);
    }
    later.assign(m + 1, 0.0);
    for (size_t i = m; i-- > 0;) later[i] = later[i + 1] + gain[size_t(route[i])] * std::exp(-lambda * finish[i + 1]);
    for (int c = 0; c < p.num_cities; ++c) {
      if (assigned[size_t(c)] || !p.eligible(r, c)) continue;
      // Cheapest position: least added time (ties: earliest).
      size_t at = 0;
      double added = kInfinity;
      for (size_t i = 0; i <= m; ++i) {
        const int prev = i == 0 ? p.depot(r) : route[i - 1];
        double d = p.travel_cost(s, prev, c) + p.execution_cost(s, c);
        if (i < m) d += p.travel_cost(s, c, route[i]) - p.travel_cost(s, prev, route[i]);
        if (d < added) added = d, at = i;
      }
      if (!std::isfinite(added)) continue;
      const int prev = at == 0 ? p.depot(r) : route[at - 1];
      const double done = finish[at] + p.travel_cost(s, prev, c) + p.execution_cost(s, c);
      // The new city's discounted gain, less what the delay costs the cities after it.
      const double increment = gain[size_t(c)] * std::exp(-lambda * done) - (1.0 - std::exp(-lambda * added)) * later[at];
      if (best.robot < 0 || increment > best.increment) best = {r, c, int(at), increment};
    }
  }
  return best;
}

void two_opt_route(const MtspProblem& p, int robot, Route& route) {
  // Reversing route[i..j] changes the legs into i and out of j and turns the inner legs
  // around (travel may be asymmetric); the execution costs stay. O(n^2) per pass.
  const int s = p.robots[size_t(robot)].species;
  const size_t n = route.size();
  for (bool improved = true; improved;) {
    improved = false;
    for (size_t i = 0; i + 1 < n && !improved; ++i) {
      const int prev = i == 0 ? p.depot(robot) : route[i - 1];
      double forward = 0.0, backward = 0.0;
      for (size_t j = i + 1; j < n; ++j) {
        forward += p.travel_cost(s, route[j - 1], route[j]);
        backward += p.travel_cost(s, route[j], route[j - 1]);
        double before = p.travel_cost(s, prev, route[i]) + forward;
        double after = p.travel_cost(s, prev, route[j]) + backward;
        if (j + 1 < n) {
          before += p.travel_cost(s, route[j], route[j + 1]);
          after += p.travel_cost(s, route[i], route[j + 1]);
        }
        if (std::isfinite(after) && after < before - 1e-9) {
          std::reverse(route.begin() + long(i), route.begin() + long(j) + 1);
          improved = true;
          break;
        }
      }
    }
  }
}

std::vector<Route> greedy_allocation(const MtspProblem& p, const std::vector<double>& gain, double lambda) {
  std::vector<Route> routes(p.robots.size());
  std::vector<char> assigned(size_t(p.num_cities), 0);
  for (;;) {
    const GreedyInsertion step = best_insertion(p, routes, assigned, gain, lambda);
    if (step.robot < 0) break;
    auto& route = routes[size_t(step.robot)];
    route.insert(route.begin() + step.position, step.city);
    assigned[size_t(step.city)] = 1;
  }
  for (size_t r = 0; r < routes.size(); ++r) two_opt_route(p, int(r), routes[r]);
  return routes;
}

}  // namespace hexplore::planning
