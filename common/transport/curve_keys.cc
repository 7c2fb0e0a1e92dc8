#include "common/transport/curve_keys.h"

#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <zmq.h>

namespace hexplore::transport {

namespace {

constexpr size_t kZ85KeyChars = 40;

std::optional<std::array<uint8_t, 32>> decode_key(const std::string& z85) {
  if (z85.size() != kZ85KeyChars) return std::nullopt;
  std::array<uint8_t, 32> key{};
  if (zmq_z85_decode(key.data(), z85.c_str()) == nullptr) return std::nullopt;
  return key;
}

std::string file_of(const std::string& dir, const std::string& member, const char* suffix) {
  return (std::filesystem::path(dir) / (member + suffix)).string();
}

// The first line of `path`, trimmed of trailing white space.
std::string read_key_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("curve: cannot read " + path + " (run hexplore_keys to make the team's keys)");
  std::string line;
  std::getline(in, line);
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  if (!is_z85_key(line)) throw std::runtime_error("curve: " + path + " does not hold a Z85 key (40 characters)");
  return line;
}

void write_file(const std::string& path, const std::string& text, mode_t mode) {
  {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw std::runtime_error("curve: cannot write " + path);
    out << text << '\n';
    if (!out) throw std::runtime_error("curve: cannot write " + path);
  }
  if (::chmod(path.c_str(), mode) != 0) throw std::runtime_error("curve: cannot set the mode of " + path);
}

}  // namespace

CurveKeyPair generate_curve_key_pair() {
  char pub[kZ85KeyChars + 1], sec[kZ85KeyChars + 1];
  if (zmq_curve_keypair(pub, sec) != 0)
    throw std::runtime_error(std::string("curve: cannot make a key pair: ") + zmq_strerror(zmq_errno()) +
                             " (is libzmq built with CURVE?)");
  return CurveKeyPair{pub, sec};
}

bool is_z85_key(const std::string& z85) { return decode_key(z85).has_value(); }

void write_curve_key_pair(const std::string& dir, const std::string& member, const CurveKeyPair& pair) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw std::runtime_error("curve: cannot create " + dir + ": " + error.message());
  // The secret first, born private: a crash between the two leaves no public key without one.
  write_file(file_of(dir, member, ".secret"), pair.secret_key, 0600);
  write_file(file_of(dir, member, ".public"), pair.public_key, 0644);
}

int write_missing_curve_key_pairs(const std::string& dir, const std::vector<std::string>& members, bool replace) {
  int made = 0;
  for (const auto& m : members) {
    if (!replace && std::filesystem::exists(file_of(dir, m, ".secret")) && std::filesystem::exists(file_of(dir, m, ".public")))
      continue;
    write_curve_key_pair(dir, m, generate_curve_key_pair());
    ++made;
  }
  return made;
}

std::shared_ptr<const CurveKeyring> CurveKeyring::load(const std::string& dir, const std::vector<std::string>& members) {
  auto ring = std::make_shared<CurveKeyring>();
  ring->dir_ = dir;
  for (const auto& m : members) {
    const std::string path = file_of(dir, m, ".public");
    const std::string z85 = read_key_file(path);
    const auto key = decode_key(z85);
    if (!ring->member_by_key_.emplace(*key, m).second)
      throw std::runtime_error("curve: " + path + " repeats the public key of '" + ring->member_by_key_.at(*key) +
                               "' (every member needs its own pair)");
    ring->public_z85_[m] = z85;
  }
  return ring;
}

const std::string& CurveKeyring::public_key(const std::string& member) const {
  const auto it = public_z85_.find(member);
  if (it == public_z85_.end()) throw std::invalid_argument("curve: no public key for '" + member + "' in " + dir_);
  return it->second;
}

std::optional<std::string> CurveKeyring::member_of(const uint8_t* key32) const {
  std::array<uint8_t, 32> key{};
  std::memcpy(key.data(), key32, key.size());
  const auto it = member_by_key_.find(key);
  if (it == member_by_key_.end()) return std::nullopt;
  return it->second;
}

CurveKeyPair CurveKeyring::own_pair(const std::string& member) const {
  const std::string path = file_of(dir_, member, ".secret");
  CurveKeyPair pair{public_key(member), read_key_file(path)};
  char derived[kZ85KeyChars + 1];
  if (zmq_curve_public(derived, pair.secret_key.c_str()) != 0 || pair.public_key != derived)
    throw std::runtime_error("curve: " + path + " is not the secret of " + file_of(dir_, member, ".public"));
  return pair;
}

}  // namespace hexplore::transport
