#pragma once
// The team file's CURVE keys as the transport wants them: the keyring of every member (each
// robot and the station) from `transport.curve_keys_dir`, and one member's credentials.

#include <memory>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/transport/curve_keys.h"

namespace hexplore::service {

// The members that hold a key pair: every robot, then the station.
std::vector<std::string> key_members(const core::TeamConfig& team);

// Null when the team file names no key folder (plain ZeroMQ). Throws core::ConfigError naming
// the team file and the missing or malformed key file.
std::shared_ptr<const transport::CurveKeyring> team_keyring(const core::TeamConfig& team);

// `member`'s pair and the team's public keys; null when `keyring` is null. Throws
// core::ConfigError when the member's secret is missing or does not match its public key.
std::shared_ptr<const transport::CurveCredentials> member_credentials(
    const core::TeamConfig& team, const std::shared_ptr<const transport::CurveKeyring>& keyring,
    const std::string& member);

// Makes the key pair of every member (robots, station) that has none yet in the team file's
// key folder (all of them with `replace`); returns how many it made. What a launcher calls
// before it starts a team, and hexplore_keys. Throws std::runtime_error naming the file it
// cannot write.
int make_missing_team_keys(const core::TeamConfig& team, bool replace = false);

}  // namespace hexplore::service
