// The EchoService as its own process, through run_service_main:
//   echo_service --config TEAM.yaml --robot ID [--kind sim|mapping|...] [base flags]
// or composed (hlmap and planning echo services for every --robot, inproc), through
// run_composition_main:
//   echo_service --composed yes --config TEAM.yaml --robot A --robot B [base flags]
#include <cstring>
#include <iostream>

#include "common/service/option_catalogue.h"
#include "tests/service/echo_service.h"

int main(int argc, char** argv) {
  using namespace hexplore;
  // Its own options, beside hexplore's services' (a host refuses options no service reads).
  service::add_service_options({{"composed", "echo", "yes: hlmap and planning echo services for every --robot"},
                                {"kind", "echo", "the service kind it stands in for (mapping)"},
                                {"throw-after-ms", "echo", "a callback throws after this long (the failure exit code)"}});
  core::ServiceKind kind = core::ServiceKind::kMapping;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--composed") == 0 && std::strcmp(argv[i + 1], "yes") == 0) {
      return service::run_composition_main(
          argc, argv,
          {[] { return std::make_unique<testing::EchoService>(core::ServiceKind::kHlmap); },
           [] { return std::make_unique<testing::EchoService>(core::ServiceKind::kPlanning); }});
    }
    if (std::strcmp(argv[i], "--kind") != 0) continue;
    const auto parsed = core::service_from_name(argv[i + 1]);
    if (!parsed) {
      std::cerr << "error: --kind: unknown service '" << argv[i + 1] << "'\n";
      return 2;
    }
    kind = *parsed;
  }
  return service::run_service_main(argc, argv, [kind] { return std::make_unique<testing::EchoService>(kind); });
}
