// hexplore_team: a whole team in one process (the launcher's fast mode).
//   hexplore_team --config TEAM.yaml --robot ID [--robot ID ...] [--results DIR] [--log-level L] [...]
// Every service of every listed robot and the station run on their own loop threads over
// inproc transport; the process ends when the station ends the mission (or a service fails).
#include <memory>

#include "common/service/service.h"
#include "services/hlmap/hlmap_service.h"
#include "services/mapping/mapping_service.h"
#include "services/planning/planning_service.h"
#include "services/safety/safety_service.h"
#include "services/sim/sim_service.h"
#include "services/station/station_service.h"

int main(int argc, char** argv) {
  using namespace hexplore;
  const std::vector<service::ServiceFactory> robot_services = {
      [] { return std::make_unique<sim::SimService>(); },
      [] { return std::make_unique<mapping::MappingService>(); },
      [] { return std::make_unique<hlmap::HlmapService>(); },
      [] { return std::make_unique<planning_service::PlanningService>(); },
      [] { return std::make_unique<safety::SafetyService>(); },
  };
  return service::run_team_main(argc, argv, robot_services,
                                [] { return std::make_unique<station::StationService>(); });
}
