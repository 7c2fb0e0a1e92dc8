#pragma once
// Local improvement of an HMDMTSP solution under the full fitness: 2-opt inside each route
// and relocation of one city to any position of any robot that may serve it (same robot
// included, i.e. or-opt of length 1). First-improvement passes until no move helps or the
// deadline passes. Not part of the paper's GA; an optional memetic step (see GaOptions).

#include <cstdint>
#include <vector>

#include "common/planning/mtsp/mtsp_fitness.h"

namespace hexplore::planning {

struct LocalSearchStats {
  int passes = 0;
  int moves = 0;
  double fitness_before = 0.0;
  double fitness_after = 0.0;
};

// Which clock a time budget counts: wall time (monotonic), or the CPU time of the calling
// thread (benchmarks on a shared, loaded machine).
enum class BudgetClock { kWall, kThreadCpu };
int64_t budget_clock_ns(BudgetClock clock);

// Improves `routes` in place; never makes the fitness worse. deadline_ns: nanoseconds of
// `clock` after which it stops between moves; 0 = no deadline.
LocalSearchStats local_search(const FitnessModel& model, std::vector<Route>& routes, int64_t deadline_ns = 0,
                              int max_passes = 1000, BudgetClock clock = BudgetClock::kWall);

}  // namespace hexplore::planning
