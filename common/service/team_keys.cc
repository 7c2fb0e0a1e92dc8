#include "common/service/team_keys.h"

#include <stdexcept>
#include <vector>

#include "common/core/config_error.h"
#include "common/core/endpoints.h"

namespace hexplore::service {

std::vector<std::string> key_members(const core::TeamConfig& team) {
  std::vector<std::string> members;
  for (const auto& r : team.robots) members.push_back(r.id);
  members.emplace_back(core::kStationId);
  return members;
}

std::shared_ptr<const transport::CurveKeyring> team_keyring(const core::TeamConfig& team) {
  if (team.transport.curve_keys_dir.empty()) return nullptr;
  try {
    return transport::CurveKeyring::load(team.transport.curve_keys_dir, key_members(team));
  } catch (const std::runtime_error& e) {
    throw core::ConfigError(team.source_file, "transport.curve_keys_dir", e.what());
  }
}

std::shared_ptr<const transport::CurveCredentials> member_credentials(
    const core::TeamConfig& team, const std::shared_ptr<const transport::CurveKeyring>& keyring,
    const std::string& member) {
  if (!keyring) return nullptr;
  auto credentials = std::make_shared<transport::CurveCredentials>();
  credentials->member = member;
  credentials->keyring = keyring;
  try {
    credentials->own = keyring->own_pair(member);
  } catch (const std::exception& e) {
    throw core::ConfigError(team.source_file, "transport.curve_keys_dir", e.what());
  }
  return credentials;
}

int make_missing_team_keys(const core::TeamConfig& team, bool replace) {
  if (team.transport.curve_keys_dir.empty()) return 0;
  return transport::write_missing_curve_key_pairs(team.transport.curve_keys_dir, key_members(team), replace);
}

}  // namespace hexplore::service
