// The team file as every service, the launcher and the station load it. A broken file must
// end in core::ConfigError (file, key, problem), never in a crash or another exception.

#include <string>

#include "common/core/config_error.h"
#include "common/core/team_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const core::TeamConfig team = core::parse_team_config(text, "fuzz.yaml");
    for (const auto& robot : team.robots) team.find_species(robot.species);
  } catch (const core::ConfigError&) {
  }
  return 0;
}
