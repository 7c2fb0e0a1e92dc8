#include "common/transport/type_id.h"

#include <cstdio>
#include <map>
#include <mutex>

#include "common/core/log.h"

namespace hexplore::transport {
namespace {

std::mutex& names_mutex() {
  static std::mutex m;
  return m;
}
std::map<uint16_t, std::string>& names() {
  static std::map<uint16_t, std::string> n;
  return n;
}

}  // namespace

uint16_t type_id(std::string_view full_name) {
  uint32_t h = 2166136261u;
  for (char c : full_name) {
    h ^= static_cast<uint8_t>(c);
    h *= 16777619u;
  }
  const uint16_t folded = static_cast<uint16_t>((h >> 16) ^ (h & 0xffff));
  return folded == 0 ? 1 : folded;  // 0 means "no payload"
}

void remember_type_name(std::string_view full_name) {
  const uint16_t id = type_id(full_name);
  std::lock_guard lock(names_mutex());
  auto [it, fresh] = names().emplace(id, std::string(full_name));
  if (!fresh && it->second != full_name)
    core::log_once(core::LogLevel::kError, "transport", "type-id-collision:" + std::to_string(id),
                   "payload types '" + it->second + "' and '" + std::string(full_name) +
                       "' share wire type id " + std::to_string(id) + ": receivers cannot tell them apart");
}

std::string type_label(uint16_t id) {
  {
    std::lock_guard lock(names_mutex());
    if (auto it = names().find(id); it != names().end()) return it->second;
  }
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "type 0x%04x", id);
  return buffer;
}

}  // namespace hexplore::transport
