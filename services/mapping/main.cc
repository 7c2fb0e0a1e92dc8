// hexplore_mapping --config TEAM.yaml --robot ID [--map-file PATH] [--publish-period-s 0.5]
//   [--full-snapshot-period-s 30] [--save-period-s 60] [--max-pose-jump-m 5] [--reanchor-after 10]
//   [--teammate-timeout-s S (default: params.liveness.body_filter_s)]
#include <memory>

#include "common/service/service.h"
#include "services/mapping/mapping_service.h"

int main(int argc, char** argv) {
  return hexplore::service::run_service_main(
      argc, argv, [] { return std::make_unique<hexplore::mapping_service::MappingService>(); });
}
