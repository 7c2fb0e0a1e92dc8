// hexplore_safety --config TEAM.yaml --robot ID [--wait-for-start true]
#include <memory>

#include "common/service/service.h"
#include "services/safety/safety_service.h"

int main(int argc, char** argv) {
  return hexplore::service::run_service_main(
      argc, argv, [] { return std::make_unique<hexplore::safety_service::SafetyService>(); });
}
