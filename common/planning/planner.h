#pragma once
// A swappable team planner (nav2-style life cycle): configured once with the team and the
// parameters, activated when chosen, asked to plan one round at a time, deactivated when
// another planner takes over. Implementations keep no globals; one instance per service.

#include <memory>
#include <string>

#include "common/planning/capabilities.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

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
  // Whether the team solution travels to the teammates as the exploration route (team/plan
  // sequences). Planners that coordinate only through identical inputs (MROMT+, TSPGA+)
  // share nothing of it; the service then publishes the solution without sequences.
  virtual bool shares_route() const { return true; }
};

}  // namespace hexplore::planning
