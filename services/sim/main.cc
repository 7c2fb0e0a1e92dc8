// hexplore_sim --config TEAM.yaml --robot ID [--scan-hz 2] [--step-hz 20] [--real-time-factor 1]
//              [--scene-dir DIR]
#include <memory>

#include "common/service/service.h"
#include "services/sim/sim_service.h"

int main(int argc, char** argv) {
  return hexplore::service::run_service_main(argc, argv,
                                             [] { return std::make_unique<hexplore::sim_service::SimService>(); });
}
