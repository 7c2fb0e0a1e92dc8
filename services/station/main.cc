// hexplore_station: the ground station process.
//   hexplore_station --config TEAM.yaml [--results DIR] [--snapshot-period-s S] [--autostart true|false]
//                    [--report true|false] [--report-script PATH]   (figures: tools/report/run_report.py)
//   hexplore_station --config TEAM.yaml --send start|stop|estop|planner=<name>   (relay one command to a running station)
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/core/config_error.h"
#include "common/core/endpoints.h"
#include "common/service/service.h"
#include "common/service/team_keys.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/status.pb.h"
#include "services/station/station_service.h"

namespace {

// Sends one mission command to the running station's ROUTER socket; returns the exit code.
int send_command(const std::string& config_path, const std::string& what) {
  using namespace hexplore;
  core::TeamConfig team;
  try {
    team = core::load_team_config(config_path);
  } catch (const core::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  v1::MissionCommand command;
  if (what == "start") command.mutable_start();
  else if (what == "stop") command.mutable_stop();
  else if (what == "estop") command.mutable_emergency_stop()->set_reason("operator");
  else if (what.rfind("planner=", 0) == 0) command.mutable_switch_planner()->set_planner(what.substr(8));
  else {
    std::fprintf(stderr, "error: --send expects start, stop, estop or planner=<name>, got '%s'\n", what.c_str());
    return 2;
  }
  // On authenticated links the operator speaks with the station's key (the only one the station
  // takes commands from).
  transport::SocketOptions options = service::team_socket_options(team);
  try {
    options.curve = service::member_credentials(team, service::team_keyring(team), std::string(core::kStationId));
  } catch (const core::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  transport::Context context;
  transport::Requester requester(
      context, {"station-cli", "", "station"},
      core::connect_endpoint(team, std::string(core::kStationId), core::ServiceKind::kStation, core::SocketRole::kRequest),
      options, nullptr, std::string(core::kStationId));
  const auto reply = requester.call<v1::MissionCommand, v1::ServiceStatus>(command, std::chrono::milliseconds(3000));
  if (!reply) {
    std::fprintf(stderr, "error: no station answered at %s\n",
                 core::connect_endpoint(team, std::string(core::kStationId), core::ServiceKind::kStation,
                                        core::SocketRole::kRequest)
                     .c_str());
    return 1;
  }
  std::printf("%s\n", reply->detail().c_str());
  return reply->detail().rfind("refused", 0) == 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string config, send;
  bool has_robot = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--robot") == 0) has_robot = true;
    if (i + 1 >= argc) continue;
    if (std::strcmp(argv[i], "--config") == 0) config = argv[i + 1];
    if (std::strcmp(argv[i], "--send") == 0) send = argv[i + 1];
  }
  if (!send.empty()) return send_command(config, send);
  // The station is one per team; its identity is fixed, so --robot is optional.
  std::vector<char*> args(argv, argv + argc);
  std::string robot_flag = "--robot", station_id(hexplore::core::kStationId);
  if (!has_robot) {
    args.push_back(robot_flag.data());
    args.push_back(station_id.data());
  }
  return hexplore::service::run_service_main(static_cast<int>(args.size()), args.data(),
                                             [] { return std::make_unique<hexplore::station_service::StationService>(); });
}
