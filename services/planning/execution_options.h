#pragma once
// How this robot executes its routes, read from the planning service's command line and its
// species: the give-up rules, the route follower's options and what counts as observed in
// passing. A bad value throws service::OptionError naming the option.

#include "common/core/team_config.h"
#include "common/planning/capabilities.h"
#include "common/planning/give_up_ledger.h"
#include "common/planning/passing_observer.h"
#include "common/planning/route_follower.h"
#include "common/service/options.h"

namespace hexplore::planning_service {

struct ExecutionOptions {
  planning::GiveUpRules give_up;
  planning::FollowerOptions follow;
  planning::PassingOptions passing;
};

// `capability`: the species' entry in the team's capabilities; `planner`: the round's options
// (its observation-angle bounds limit what is seen in passing).
ExecutionOptions execution_options(const service::Options& opts, const core::SpeciesConfig& species,
                                   const planning::SpeciesCapability& capability,
                                   const planning::PlannerOptions& planner);

}  // namespace hexplore::planning_service
