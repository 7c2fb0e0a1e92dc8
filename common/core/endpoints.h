#pragma once
// Where each service of each robot listens. Every service binds one PUB socket (all topics it
// publishes) and one ROUTER socket (requests: snapshots, repairs). Addresses derive from the
// team's TransportConfig so that a team file is all a launcher or a container needs.

#include <optional>
#include <string>
#include <string_view>

#include "common/core/team_config.h"

namespace hexplore::core {

enum class ServiceKind { kSim = 0, kMapping = 1, kHlmap = 2, kPlanning = 3, kSafety = 4, kStation = 5 };
enum class SocketRole { kPublish = 0, kRequest = 1 };

std::string_view service_name(ServiceKind kind);
// nullopt for an unknown name.
std::optional<ServiceKind> service_from_name(std::string_view name);

// The station counts as one extra robot slot after the last robot.
constexpr std::string_view kStationId = "station";

// Port of (robot, service, role) for tcp; throws ConfigError for an unknown robot id.
int endpoint_port(const TeamConfig& config, const std::string& robot_id, ServiceKind service, SocketRole role);
// Address to bind, e.g. "tcp://*:17002", "ipc:///tmp/hexplore/r1-hlmap-pub", "inproc://r1-hlmap-pub".
std::string bind_endpoint(const TeamConfig& config, const std::string& robot_id, ServiceKind service, SocketRole role);
// Address to connect to the same socket from another process or container.
std::string connect_endpoint(const TeamConfig& config, const std::string& robot_id, ServiceKind service, SocketRole role);
// `text` with every "{name}" replaced by `value`: the team file's host_template
// ("{robot}-{service}") and per-robot paths in options every process receives alike
// (mapping's --map-file maps/{robot}.map).
std::string substitute(std::string text, std::string_view name, const std::string& value);

// Prometheus exposer port of a service; 0 when metrics are off.
int metrics_port(const TeamConfig& config, const std::string& robot_id, ServiceKind service);

}  // namespace hexplore::core
