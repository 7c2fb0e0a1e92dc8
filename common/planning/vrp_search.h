#pragma once
// A multi-depot vehicle-routing solver in the manner of OR-Tools' routing library, for the
// MDVRP+ baseline (after MUI-TARE / M-TARE): one vehicle per robot with its own cost matrix
// (+inf where the robot cannot serve a node), open routes from each depot, objective
//   sum of route costs + max_weight * longest route cost + drop_penalty * dropped nodes,
// a cheapest-insertion start, then guided local search (arc penalties, Voudouris & Tsang)
// over relocate, exchange, 2-opt, or-opt (segments of 1-3, either direction) and 2-opt*
// (tail swap) moves on neighbour lists, with "don't look" bits, until an evaluation budget
// or a time budget ends. Independent of maps: costs come in as matrices.

#include <cstdint>
#include <vector>

#include "common/planning/local_search.h"
#include "common/planning/mtsp_problem.h"

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

struct GlsOptions {
  int64_t max_evaluations = 0;   // move evaluations; 0 = no limit (then time must bound it)
  double time_budget_s = 0.0;    // 0 = no time limit
  BudgetClock clock = BudgetClock::kWall;
  uint64_t seed = 1;             // order in which customers are scanned
  int neighbours = 20;           // per customer and class, the nearest customers by travel time
  double lambda_coefficient = 0.3;  // lambda = coefficient * mean arc cost of the first local optimum
};

struct GlsResult {
  VrpRoutes routes;
  VrpCost cost;
  VrpCost start_cost;
  int64_t evaluations = 0;
  int64_t moves = 0;
  int local_optima = 0;
  double elapsed_s = 0.0;
};

// Improves `start` (customers may appear once at most; an ineligible placement is allowed but
// costs +inf, so the search moves it away when it can). The result is the best solution met by
// the true objective, so never worse than the start. Throws std::invalid_argument for
// inconsistent sizes or a customer placed twice.
GlsResult guided_local_search(const VrpInstance& instance, const VrpRoutes& start, const GlsOptions& options);

}  // namespace hexplore::planning
