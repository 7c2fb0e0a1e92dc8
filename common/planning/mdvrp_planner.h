#pragma once
// MDVRP+ (BASELINES.md; after MUI-TARE, Yan et al., RA-L 2023, and its public M-TARE
// planner): every task view is a node of a multi-depot vehicle-routing problem with one
// vehicle per robot and per-robot costs in seconds (+inf where the robot's capability or
// reach does not match), objective sum + 100 x longest route + drop penalty, warm-started
// from the best shared previous solution and improved by guided local search under the
// GA's budget. The team solution (view keys in visiting order) is shared as its
// exploration route; the planning robot executes its own part.

#include <cstdint>
#include <string>

#include "common/planning/planner_base.h"

namespace hexplore::planning {

// The lockstep budget (BASELINES.md "same budget"): the GA is bounded by generations there,
// so MDVRP+ gets this many guided-local-search move evaluations per GA generation. Set so
// that on the paper-sized planning benchmark (bench_planning_round) the search takes about
// the GA's wall budget (ga_time_budget_s, the paper's 50 ms) of CPU time; see
// common/planning/README.md "Baselines".
inline constexpr int64_t kMdvrpEvaluationsPerGeneration = 1000;

class MdvrpPlanner : public ConfiguredPlanner {
 public:
  std::string name() const override { return "mdvrp+"; }
  PlanResult plan(const PlanRequest& request) override;
  RouteSharing route_sharing() const override { return RouteSharing::kEverySolution; }
};

}  // namespace hexplore::planning
