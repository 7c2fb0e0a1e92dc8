#pragma once
// The improved genetic algorithm for the HMDMTSP (paper "Population Generation", "Mutation
// Operations", "Fitness Function"): multi-chromosome individuals (one route per robot);
// public cities are joined to a species at birth, then each species' set is split among its
// robots; mutations act on each species' merged set and are redistributed; selection keeps
// the best of random groups (group of 8: the best plus its mutants, as in the multi-chromosome
// mTSP GA). Deterministic for a seed under a generation budget.

#include <cstdint>
#include <functional>
#include <vector>

#include "common/planning/mtsp/local_search.h"
#include "common/planning/mtsp/mtsp_fitness.h"

namespace hexplore::planning {

enum class LocalSearchMode {
  kNone,     // the paper's mutation-only GA
  kFinal,    // local search on the final best
  kMemetic,  // also on every new global best during the run, fed back into the population
  kOffspring,  // on every mutant (a memetic GA: mutations perturb local optima)
};

struct GaOptions {
  int population = 64;            // rounded up to a multiple of the group size (8)
  int max_generations = 400;      // deterministic budget; 0 = unbounded (then time must bound it)
  double time_budget_s = 0.0;     // 0 = no time limit; a time limit makes the result timing-dependent
  BudgetClock budget_clock = BudgetClock::kWall;
  int stall_generations = 0;      // stop after this many generations without improvement; 0 = never
  uint64_t seed = 1;
  bool use_inversion = false;     // add inversion to the paper's swap / shift / shuffle
  // The paper fixes which species serves a public city at birth. With this on, one more
  // mutant per group moves a public city to a robot of another species; without it tiny
  // instances can miss the optimum when the right species split died out early.
  bool public_transfer = true;
  LocalSearchMode local_search = LocalSearchMode::kNone;
  // Extra starting individuals (e.g. the reference solution mapped onto this round); invalid
  // ones (wrong size, duplicate or missing cities, ineligible robot) are ignored.
  std::vector<std::vector<Route>> seeds;
};

struct GaResult {
  std::vector<Route> routes;      // per robot
  FitnessModel::Breakdown breakdown;
  double initial_best_fitness = 0.0;
  int generations = 0;
  int64_t evaluations = 0;
  double elapsed_s = 0.0;
  bool feasible = false;          // no infinite leg, execution or label mismatch
};

// Solves the problem; throws std::invalid_argument for an invalid problem (see validate()).
GaResult solve_ga(const FitnessModel& model, const GaOptions& options);

// Exhaustive optimum for tiny instances (tests, verification): every assignment and order.
// Throws std::invalid_argument above 9 cities.
GaResult solve_brute_force(const FitnessModel& model);

}  // namespace hexplore::planning
