#pragma once
// CURVE keys of a team (ZeroMQ's CurveZMQ: Curve25519 key exchange, then every frame encrypted
// and authenticated). Each member (every robot, and the station) has a key pair; a team's keys
// live in one folder, one pair per member:
//   DIR/<member>.public   the public key, Z85 (40 characters), what every teammate must hold
//   DIR/<member>.secret   the secret key, Z85, mode 0600, only for the member's own processes
// `hexplore_keys` writes them. A socket that binds on tcp is a CURVE server holding its
// member's secret key; a socket that connects is a client that holds its own pair and must know
// the public key of the member it connects to, so that a process squatting on a teammate's
// port without that member's secret key cannot complete the handshake.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hexplore::transport {

struct CurveKeyPair {
  std::string public_key;  // Z85, 40 characters
  std::string secret_key;  // Z85, 40 characters
};

// A fresh pair from libzmq (libsodium's randomness). Throws std::runtime_error when the ZeroMQ
// library was built without CURVE.
CurveKeyPair generate_curve_key_pair();

// Whether `z85` is a well-formed Z85 key (40 characters that decode to 32 bytes).
bool is_z85_key(const std::string& z85);

// Writes DIR/<member>.public and DIR/<member>.secret (the folder is created; the secret file
// gets mode 0600). Throws std::runtime_error naming the file that could not be written.
void write_curve_key_pair(const std::string& dir, const std::string& member, const CurveKeyPair& pair);

// Writes a fresh pair for every member of `members` that has no complete pair in `dir` yet (for
// every one with `replace`); returns how many it wrote. Throws like write_curve_key_pair.
int write_missing_curve_key_pairs(const std::string& dir, const std::vector<std::string>& members, bool replace = false);

// The public keys of every member of a team, and the folder they came from.
class CurveKeyring {
 public:
  // Reads DIR/<m>.public for every member `m`; throws std::runtime_error naming the missing or
  // malformed file (a team with authentication on must not start with a member it cannot check).
  static std::shared_ptr<const CurveKeyring> load(const std::string& dir, const std::vector<std::string>& members);

  const std::string& dir() const { return dir_; }
  // The member's public key (Z85); throws std::invalid_argument for a name not in the team.
  const std::string& public_key(const std::string& member) const;
  // The member a 32-byte binary public key belongs to (as the ZAP handler receives it).
  std::optional<std::string> member_of(const uint8_t* key32) const;
  // The member's own pair, its secret read from DIR/<member>.secret; throws std::runtime_error
  // naming the file when it is missing or malformed, or when it does not match the public key.
  CurveKeyPair own_pair(const std::string& member) const;
  size_t size() const { return public_z85_.size(); }

 private:
  std::string dir_;
  std::map<std::string, std::string> public_z85_;                 // member -> Z85
  std::map<std::array<uint8_t, 32>, std::string> member_by_key_;  // binary key -> member
};

// What a socket needs to speak CURVE: its member's pair and the team's public keys.
struct CurveCredentials {
  std::string member;  // whose pair this is (a robot id or "station")
  CurveKeyPair own;
  std::shared_ptr<const CurveKeyring> keyring;
};

}  // namespace hexplore::transport
