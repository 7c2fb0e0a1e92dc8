// hexplore_planning --config TEAM.yaml --robot ID [--wait-for-start true] [--cycle-ms N]
#include <memory>

#include "common/service/service.h"
#include "services/planning/planning_service.h"

int main(int argc, char** argv) {
  return hexplore::service::run_service_main(
      argc, argv, [] { return std::make_unique<hexplore::planning_service::PlanningService>(); });
}
