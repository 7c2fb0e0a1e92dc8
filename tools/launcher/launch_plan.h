#pragma once
// Which processes a team needs: one per (robot, service) plus the optional station, each with
// its executable and arguments. Executables are looked up before anything starts, so a missing
// one is reported by name instead of failing half-way through a launch.

#include <optional>
#include <string>
#include <vector>

#include "common/core/team_config.h"

namespace hexplore::launcher {

// One process to start.
struct ProcessSpec {
  std::string name;                  // "r1/sim", "station": prefix of its output lines
  std::string robot_id;              // "station" for the station
  std::string service;               // "sim", "mapping", ...
  std::string executable;            // resolved path ("" when not found)
  std::vector<std::string> arguments;  // argv[1..]
  bool is_station = false;
  bool ends_launch = false;            // its exit ends the launch with its exit code
};

struct LaunchRequest {
  std::string config_path;
  std::vector<std::string> bin_dirs;       // searched in order; empty -> defaults next to the launcher
  std::vector<std::string> robots;         // empty = every robot of the team
  std::vector<std::string> services;       // empty = the five robot services + station if built
  std::vector<std::string> extra_arguments;  // appended to every child's arguments
  // Fast mode: instead of one process per service, this one executable hosts every service of
  // the selected robots (run with --config FILE --robot A --robot B ...); "" = off.
  std::string compose_executable;
};

// The five per-robot services in start order.
const std::vector<std::string>& robot_services();
// "hexplore_<service>".
std::string executable_name(const std::string& service);

// Search folders used when the request names none: the launcher's own folder and, for a build
// tree, <build>/services/<service>/ (the launcher lives in <build>/tools/launcher/).
std::vector<std::string> default_bin_dirs(const std::string& launcher_path, const std::string& service);

struct LaunchPlan {
  std::vector<ProcessSpec> processes;
  std::vector<std::string> missing;        // one line per executable that was not found
};

// Builds the plan; throws std::invalid_argument for unknown robots or services (listing the
// known ones). The station is included when asked for, or when not filtered and its
// executable exists; it ends the launch. In fast mode the composed process ends the launch
// when there is no station.
LaunchPlan plan_launch(const core::TeamConfig& team, const LaunchRequest& request, const std::string& launcher_path);

// Splits "a,b,c" (empty items dropped).
std::vector<std::string> split_list(const std::string& text);

}  // namespace hexplore::launcher
