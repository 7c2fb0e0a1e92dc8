#pragma once
// The multi-depot vehicle-routing problem of the MDVRP+ baseline (after MUI-TARE / M-TARE):
// one vehicle per robot with its own cost matrix (+inf where the robot cannot serve a node),
// open routes from each depot, objective
//   sum of route costs + max_weight * longest route cost + drop_penalty * dropped nodes,
// and the cheapest-insertion construction. The search is vrp_search.h. Independent of maps:
// costs come in as matrices.

#include <vector>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

struct VrpInstance {
  int customers = 0;                 // nodes 0..customers-1; vehicle v's depot is customers + v
  std::vector<int> vehicle_class;    // per vehicle: index into travel / service (e.g. species)
  std::vector<CostMatrix> travel;    // per class, (customers + vehicles)^2; +inf = impassable
  std::vector<std::vector<double>> service;  // per class per customer; +inf = cannot serve
  double max_weight = 100.0;         // M-TARE's global span coefficient
  double drop_penalty = 1e7;         // per unserved customer, far above any route cost

  int vehicles() const { return int(vehicle_class.size()); }
  int depot(int vehicle) const { return customers + vehicle; }
  // The vehicle may serve the customer: finite service and a finite way from its depot.
  bool eligible(int vehicle, int customer) const;
};

using VrpRoutes = std::vector<std::vector<int>>;  // per vehicle, customers in visiting order

struct VrpCost {
  int dropped = 0;
  double total = 0.0;    // sum of route costs
  double longest = 0.0;  // the largest route cost
  double objective = 0.0;
  bool feasible = true;  // no infinite leg or service in any route
};

// Cost of one route / of a whole solution (a customer in no route counts as dropped).
double vrp_route_cost(const VrpInstance& instance, int vehicle, const std::vector<int>& route);
VrpCost vrp_cost(const VrpInstance& instance, const VrpRoutes& routes);

// Inserts every customer missing from `routes` that some vehicle may serve, in the order of
// `order` (customers already routed or unservable are skipped), each at the position of
// least objective increase over all vehicles (ties: lower vehicle, earlier position).
// Customers no vehicle may serve stay dropped.
VrpRoutes cheapest_insertion(const VrpInstance& instance, VrpRoutes routes, const std::vector<int>& order);

}  // namespace hexplore::planning
