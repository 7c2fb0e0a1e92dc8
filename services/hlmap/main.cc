// hexplore_hlmap --config TEAM.yaml --robot ID [--fault-drop F --fault-topics team/map ...]
#include <memory>

#include "common/service/service.h"
#include "services/hlmap/hlmap_service.h"

int main(int argc, char** argv) {
  return hexplore::service::run_service_main(argc, argv,
                                             [] { return std::make_unique<hexplore::hlmap_service::HlmapService>(); });
}
