#pragma once
// A swappable team planner (nav2-style life cycle): configured once with the team and the
// parameters, activated when chosen, asked to plan one round at a time, deactivated when
// another planner takes over. Implementations keep no globals; one instance per service.

#include <memory>
#include <string>

#include "common/planning/capabilities.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

// What the teammates make of a planner's team solution (team/plan sequences).
enum class RouteSharing {
  // Nothing: planners that coordinate only through identical inputs (MROMT+, TSPGA+). The
  // service publishes the solution without sequences.
  kNone,
  // Every shared solution is an input (MDVRP+ projects each onto its views for a warm start):
  // every new solution travels.
  kEverySolution,
  // Only the reference that select_reference chooses (hexplore and its ablations): a solution
  // no teammate would choose need not travel (reference_worth_sending).
  kReferenceOnly,
};

struct PlannerContext {
  TeamCapabilities team;
  PlannerOptions options;
};

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  virtual void configure(const PlannerContext& context) = 0;
  virtual void activate() {}
  virtual void deactivate() {}
  // One planning round; deterministic for the same request, map and options.
  virtual PlanResult plan(const PlanRequest& request) = 0;
  // How the team solution travels to the teammates as the exploration route.
  virtual RouteSharing route_sharing() const { return RouteSharing::kReferenceOnly; }
};

}  // namespace hexplore::planning
