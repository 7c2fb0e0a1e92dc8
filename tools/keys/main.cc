// hexplore_keys: makes the key pairs that authenticate and encrypt a team's links (ZeroMQ
// CURVE, common/transport/curve_keys.h): DIR/<member>.public and DIR/<member>.secret for every
// robot of the team file and for the station. DIR is the team file's transport.curve_keys_dir
// unless --out names another. Existing pairs are kept (a running team keeps working) unless
// --force; give each robot only its own .secret and everyone's .public files.
//
// Usage: hexplore_keys --config TEAM.yaml [--out DIR] [--force]
#include <cstdio>
#include <cstring>
#include <string>

#include "common/core/config_error.h"
#include "common/core/team_config.h"
#include "common/service/team_keys.h"

namespace {

int usage(const char* problem) {
  std::fprintf(stderr, "error: %s\nusage: hexplore_keys --config TEAM.yaml [--out DIR] [--force]\n", problem);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hexplore;
  std::string config, out;
  bool force = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--force") force = true;
    else if ((a == "--config" || a == "--out") && i + 1 < argc) (a == "--config" ? config : out) = argv[++i];
    else return usage(("unknown or incomplete option '" + a + "'").c_str());
  }
  if (config.empty()) return usage("--config is required");
  core::TeamConfig team;
  try {
    team = core::load_team_config(config);
  } catch (const core::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  if (!out.empty()) team.transport.curve_keys_dir = out;
  if (team.transport.curve_keys_dir.empty())
    return usage("the team file has no transport.curve_keys_dir; name the folder with --out");
  const size_t members = service::key_members(team).size();
  int made = 0;
  try {
    made = service::make_missing_team_keys(team, force);
    // Read back as the services will: every public key present, distinct, each secret its own.
    const auto ring = service::team_keyring(team);
    for (const auto& m : service::key_members(team)) service::member_credentials(team, ring, m);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("%s: %d new key pair(s), %zu members (%zu kept)\n", team.transport.curve_keys_dir.c_str(), made,
              members, members - size_t(made));
  return 0;
}
