#pragma once
// The team file's CURVE keys as the transport wants them: the keyring of every member (each
// robot and the station) from `transport.curve_keys_dir`, and one member's credentials.

#include <memory>
#include <string>

#include "common/core/team_config.h"
#include "common/transport/curve_keys.h"

namespace hexplore::service {

// Null when the team file names no key folder (plain ZeroMQ). Throws core::ConfigError naming
// the team file and the missing or malformed key file.
std::shared_ptr<const transport::CurveKeyring> team_keyring(const core::TeamConfig& team);

// `member`'s pair and the team's public keys; null when `keyring` is null. Throws
// core::ConfigError when the member's secret is missing or does not match its public key.
std::shared_ptr<const transport::CurveCredentials> member_credentials(
    const core::TeamConfig& team, const std::shared_ptr<const transport::CurveKeyring>& keyring,
    const std::string& member);

}  // namespace hexplore::service
