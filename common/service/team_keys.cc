#include "common/service/team_keys.h"

#include <stdexcept>
#include <vector>

#include "common/core/config_error.h"
#include "common/core/endpoints.h"

namespace hexplore::service {

std::shared_ptr<const transport::CurveKeyring> team_keyring(const core::TeamConfig& team) {
  if (team.transport.curve_keys_dir.empty()) return nullptr;
  std::vector<std::string> members;
  for (const auto& r : team.robots) members.push_back(r.id);
  members.emplace_back(core::kStationId);
  try {
    return transport::CurveKeyring::load(team.transport.curve_keys_dir, members);
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

}  // namespace hexplore::service
