#pragma once
// The life cycle the baseline planners share: configure() keeps the team and the options
// (a team without species is an error), and a round starts by checking the request and
// filling the result's round, planner name and view figures from the round inputs.

#include "common/planning/planner.h"
#include "common/planning/round_inputs.h"

namespace hexplore::planning {

class ConfiguredPlanner : public Planner {
 public:
  void configure(const PlannerContext& context) override;

 protected:
  // The context, once configure() ran and the request fits the team; throws std::logic_error
  // before configure(), std::invalid_argument (check_request) for a bad request.
  const PlannerContext& checked(const PlanRequest& request) const;
  // A result with the request's round, this planner's name and the views of `in`.
  PlanResult start_result(const PlanRequest& request, const RoundInputs& in) const;

 private:
  PlannerContext context_;
  bool configured_ = false;
};

}  // namespace hexplore::planning
