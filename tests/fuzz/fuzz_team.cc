#include "tests/fuzz/fuzz_team.h"

#include "common/radio/team_codecs.h"
#include "common/transport/roster.h"

namespace hexplore::fuzz {
namespace {

// deploy/teams/default.yaml's robots and species (scene and ports do not matter to a decoder).
constexpr const char* kTeamYaml = R"(scene: single-building
species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - id: slugcat1
    species: SLUGCAT
    start: [2.0, -3.0, 0.0]
  - id: mr1000a
    species: MR1000
    start: [4.0, -3.0, 0.0]
transport:
  scheme: tcp
  base_port: 17000
)";

}  // namespace

const core::TeamConfig& team() {
  static const core::TeamConfig t = core::parse_team_config(kTeamYaml, "fuzz team");
  return t;
}

const transport::SocketOptions& team_socket_options() {
  static const transport::SocketOptions options = [] {
    transport::SocketOptions o;
    o.roster = transport::Roster::from_team(team());
    o.codecs = radio::team_codecs(team());
    return o;
  }();
  return options;
}

}  // namespace hexplore::fuzz
