#include "tools/team/team_services.h"

#include <memory>

#include "services/hlmap/hlmap_service.h"
#include "services/mapping/mapping_service.h"
#include "services/planning/planning_service.h"
#include "services/safety/safety_service.h"
#include "services/sim/sim_service.h"
#include "services/station/station_service.h"

namespace hexplore::team {

std::vector<service::ServiceFactory> robot_services() {
  return {
      [] { return std::make_unique<sim_service::SimService>(); },
      [] { return std::make_unique<mapping_service::MappingService>(); },
      [] { return std::make_unique<hlmap_service::HlmapService>(); },
      [] { return std::make_unique<planning_service::PlanningService>(); },
      [] { return std::make_unique<safety_service::SafetyService>(); },
  };
}

service::ServiceFactory station_service() {
  return [] { return std::make_unique<station_service::StationService>(); };
}

}  // namespace hexplore::team
