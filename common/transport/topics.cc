#include "common/transport/topics.h"

namespace hexplore::transport::topics {
namespace {

constexpr size_t kMaxTopicLength = 128;

bool allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
         c == '-' || c == '/';
}

// Checks characters and segments; a trailing '/' is allowed only when `prefix`.
bool valid(std::string_view text, bool prefix) {
  if (text.empty() || text.size() > kMaxTopicLength || text.front() == '/') return false;
  char previous = 0;
  for (char c : text) {
    if (!allowed(c)) return false;
    if (c == '/' && previous == '/') return false;
    previous = c;
  }
  return prefix || text.back() != '/';
}

// Wire codes of the team topics, in code order (code = index + 1).
constexpr std::string_view kCoded[] = {kTeamPose, kTeamMap, kTeamPlan, kTeamPath, kTeamMission};
constexpr char kCodes[] = {'\x01', '\x02', '\x03', '\x04', '\x05'};

}  // namespace

bool is_team_topic(std::string_view topic) { return topic.substr(0, kTeamPrefix.size()) == kTeamPrefix; }

std::string_view wire_topic(std::string_view topic) {
  for (size_t i = 0; i < std::size(kCoded); ++i)
    if (kCoded[i] == topic) return std::string_view(&kCodes[i], 1);
  return topic;
}

std::optional<std::string_view> topic_from_wire(std::string_view wire) {
  if (wire.empty() || static_cast<unsigned char>(wire.front()) >= 0x20) return wire;
  if (wire.size() != 1) return std::nullopt;
  const size_t index = static_cast<unsigned char>(wire.front()) - 1;
  if (index >= std::size(kCoded)) return std::nullopt;
  return kCoded[index];
}

std::vector<std::string> wire_prefixes(std::string_view prefix) {
  std::vector<std::string> out{std::string(prefix)};
  for (size_t i = 0; i < std::size(kCoded); ++i)
    if (matches(prefix, kCoded[i])) out.emplace_back(1, kCodes[i]);
  return out;
}

std::string robot_topic(std::string_view robot_id, std::string_view leaf) {
  std::string topic;
  topic.reserve(7 + robot_id.size() + leaf.size());
  topic.append("robot/").append(robot_id).append("/").append(leaf);
  return topic;
}

std::string robot_prefix(std::string_view robot_id) {
  std::string prefix("robot/");
  prefix.append(robot_id).append("/");
  return prefix;
}

bool is_valid_topic(std::string_view topic) { return valid(topic, false); }
bool is_valid_prefix(std::string_view prefix) { return valid(prefix, true); }

bool matches(std::string_view prefix, std::string_view topic) { return topic.substr(0, prefix.size()) == prefix; }

std::string_view topic_label(std::string_view topic) { return is_valid_topic(topic) ? topic : "invalid"; }

std::string_view peer_label(std::string_view robot_id) {
  if (robot_id.empty() || robot_id.size() > 64) return "unknown";
  for (char c : robot_id)
    if (!allowed(c) || c == '/') return "unknown";
  return robot_id;
}

}  // namespace hexplore::transport::topics
