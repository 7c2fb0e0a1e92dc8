#include "common/core/endpoints.h"

#include <array>

#include "common/core/config_error.h"

namespace hexplore::core {
namespace {

constexpr std::array<std::string_view, 6> kNames = {"sim", "mapping", "hlmap", "planning", "safety", "station"};

int robot_slot(const TeamConfig& config, const std::string& robot_id) {
  if (robot_id == kStationId) return static_cast<int>(config.robots.size());
  const auto index = config.robot_index(robot_id);
  if (!index) throw ConfigError(config.source_file, "robots", "unknown robot id '" + robot_id + "'");
  return *index;
}

std::string socket_name(const std::string& robot_id, ServiceKind service, SocketRole role) {
  return robot_id + "-" + std::string(service_name(service)) + (role == SocketRole::kPublish ? "-pub" : "-req");
}

}  // namespace

std::string substitute(std::string text, std::string_view name, const std::string& value) {
  const std::string token = "{" + std::string(name) + "}";
  for (size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + value.size()))
    text.replace(at, token.size(), value);
  return text;
}

std::string_view service_name(ServiceKind kind) { return kNames[static_cast<size_t>(kind)]; }

std::optional<ServiceKind> service_from_name(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<ServiceKind>(i);
  return std::nullopt;
}

int endpoint_port(const TeamConfig& config, const std::string& robot_id, ServiceKind service, SocketRole role) {
  const auto& t = config.transport;
  return t.base_port + robot_slot(config, robot_id) * t.ports_per_robot + static_cast<int>(service) * 2 +
         static_cast<int>(role);
}

std::string bind_endpoint(const TeamConfig& config, const std::string& robot_id, ServiceKind service, SocketRole role) {
  const auto& t = config.transport;
  if (t.scheme == "inproc") return "inproc://" + socket_name(robot_id, service, role);
  if (t.scheme == "ipc") return "ipc://" + t.ipc_dir + "/" + socket_name(robot_id, service, role);
  return "tcp://*:" + std::to_string(endpoint_port(config, robot_id, service, role));
}

std::string connect_endpoint(const TeamConfig& config, const std::string& robot_id, ServiceKind service,
                             SocketRole role) {
  const auto& t = config.transport;
  if (t.scheme != "tcp") return bind_endpoint(config, robot_id, service, role);
  std::string host = substitute(t.host_template, "robot", robot_id);
  host = substitute(host, "service", std::string(service_name(service)));
  return "tcp://" + host + ":" + std::to_string(endpoint_port(config, robot_id, service, role));
}

int metrics_port(const TeamConfig& config, const std::string& robot_id, ServiceKind service) {
  if (config.metrics_base_port == 0) return 0;
  return config.metrics_base_port + robot_slot(config, robot_id) * 10 + static_cast<int>(service);
}

}  // namespace hexplore::core
