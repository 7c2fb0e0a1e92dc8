#pragma once
// Guided local search for the MDVRP+ vehicle-routing problem (vrp_instance.h), in the manner of
// OR-Tools' routing library: arc penalties (Voudouris & Tsang) over relocate, exchange, 2-opt,
// or-opt (segments of 1-3, either direction) and 2-opt* (tail swap) moves on neighbour lists,
// with "don't look" bits, until an evaluation budget or a time budget ends.

#include <cstdint>

#include "common/planning/mtsp/local_search.h"
#include "common/planning/vrp_instance.h"

namespace hexplore::planning {

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
