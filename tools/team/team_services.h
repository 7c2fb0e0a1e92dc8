#pragma once
// The services every robot of a team runs, as factories: what the one-process team
// (hexplore_team) and the experiment runner (hexplore_experiment) compose.

#include <vector>

#include "common/service/service.h"

namespace hexplore::team {

// sim, mapping, hlmap, planning, safety: in this order (lockstep runs setups in add order).
std::vector<service::ServiceFactory> robot_services();
service::ServiceFactory station_service();

}  // namespace hexplore::team
