#include "common/transport/socket_options.h"

#include <stdexcept>

namespace hexplore::transport {

bool FaultInjection::applies_to(std::string_view topic) const {
  if (topic_prefixes.empty()) return true;
  for (const auto& prefix : topic_prefixes)
    if (topic.substr(0, prefix.size()) == prefix) return true;
  return false;
}

SocketOptions SocketOptions::from_config(const core::TransportConfig& config) {
  SocketOptions options;
  options.send_high_water_mark = config.send_high_water_mark;
  options.receive_high_water_mark = config.receive_high_water_mark;
  options.max_message_bytes = config.max_message_bytes;
  options.linger_ms = config.linger_ms;
  return options;
}

void SocketOptions::validate() const {
  auto fail = [](const std::string& field, const std::string& problem) {
    throw std::invalid_argument("transport: SocketOptions." + field + " " + problem);
  };
  if (send_high_water_mark < 0) fail("send_high_water_mark", "must be >= 0");
  if (receive_high_water_mark < 0) fail("receive_high_water_mark", "must be >= 0");
  if (max_message_bytes <= 0) fail("max_message_bytes", "must be > 0");
  if (linger_ms < -1) fail("linger_ms", "must be >= -1");
  if (faults.drop_fraction < 0.0 || faults.drop_fraction > 1.0) fail("faults.drop_fraction", "must be in [0, 1]");
  if (faults.delay.count() < 0) fail("faults.delay", "must be >= 0");
  if (compress_level < 1 || compress_level > 19) fail("compress_level", "must be in [1, 19]");
  if (radio && !roster) fail("radio", "needs the roster (radio verdicts are per robot slot)");
}

}  // namespace hexplore::transport
