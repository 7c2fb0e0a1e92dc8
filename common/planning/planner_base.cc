#include "common/planning/planner_base.h"

#include <stdexcept>

namespace hexplore::planning {

void ConfiguredPlanner::configure(const PlannerContext& context) {
  if (context.team.species.empty()) throw std::invalid_argument(name() + ": team has no species");
  context_ = context;
  configured_ = true;
}

const PlannerContext& ConfiguredPlanner::checked(const PlanRequest& request) const {
  if (!configured_) throw std::logic_error(name() + ": plan() before configure()");
  check_request(name(), request, context_.team);
  return context_;
}

PlanResult ConfiguredPlanner::start_result(const PlanRequest& request, const RoundInputs& in) const {
  PlanResult out;
  out.round = request.round;
  out.planner = name();
  out.view_stats = in.stats;
  out.views = int(in.views.size());
  return out;
}

}  // namespace hexplore::planning
