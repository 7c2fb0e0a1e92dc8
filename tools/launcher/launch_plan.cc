#include "tools/launcher/launch_plan.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "common/core/endpoints.h"

namespace hexplore::launcher {
namespace {

namespace fs = std::filesystem;

bool is_executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::string find_executable(const std::vector<std::string>& dirs, const std::string& name) {
  for (const auto& dir : dirs) {
    const fs::path candidate = fs::path(dir) / name;
    if (is_executable(candidate)) return candidate.string();
  }
  return "";
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

const std::vector<std::string>& robot_services() {
  static const std::vector<std::string> services{"sim", "mapping", "hlmap", "planning", "safety"};
  return services;
}

std::string executable_name(const std::string& service) { return "hexplore_" + service; }

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::vector<std::string> default_bin_dirs(const std::string& launcher_path, const std::string& service) {
  std::error_code ec;
  fs::path self = fs::canonical(launcher_path, ec);
  if (ec) self = fs::absolute(launcher_path);
  const fs::path dir = self.parent_path();
  // The build tree mirrors the source tree: services in services/<name>, the one-process team
  // (a composition, not a service) in tools/team beside the launcher.
  const fs::path build = dir.parent_path().parent_path();
  const fs::path home = service == "team" ? build / "tools" / "team" : build / "services" / service;
  return {dir.string(), home.string()};
}

LaunchPlan plan_launch(const core::TeamConfig& team, const LaunchRequest& request, const std::string& launcher_path) {
  std::vector<std::string> services = request.services;
  const bool station_optional = services.empty();
  if (services.empty()) {
    services = robot_services();
    services.push_back("station");
  }
  for (const auto& s : services) {
    if (s != "station" && std::find(robot_services().begin(), robot_services().end(), s) == robot_services().end()) {
      throw std::invalid_argument("unknown service '" + s + "' (known: " + joined(robot_services()) + ", station)");
    }
  }
  std::vector<std::string> robots = request.robots;
  if (robots.empty()) {
    for (const auto& r : team.robots) robots.push_back(r.id);
  }
  for (const auto& id : robots) {
    if (!team.find_robot(id)) {
      std::vector<std::string> known;
      for (const auto& r : team.robots) known.push_back(r.id);
      throw std::invalid_argument("unknown robot '" + id + "' in " + team.source_file + " (known: " + joined(known) + ")");
    }
  }
  auto dirs_for = [&](const std::string& service) {
    return request.bin_dirs.empty() ? default_bin_dirs(launcher_path, service) : request.bin_dirs;
  };

  LaunchPlan plan;
  if (!request.compose_executable.empty()) {
    ProcessSpec p;
    p.name = "team";
    p.service = "team";
    p.executable = find_executable(dirs_for("team"), request.compose_executable);
    p.arguments = {"--config", request.config_path};
    for (const auto& id : robots) p.arguments.insert(p.arguments.end(), {"--robot", id});
    p.arguments.insert(p.arguments.end(), request.extra_arguments.begin(), request.extra_arguments.end());
    if (p.executable.empty()) {
      plan.missing.push_back(request.compose_executable + " (fast mode: every service in one process) not found in " +
                             joined(dirs_for("team")));
    }
    plan.processes.push_back(std::move(p));
  }
  for (const auto& id : request.compose_executable.empty() ? robots : std::vector<std::string>{}) {
    for (const auto& service : robot_services()) {
      if (std::find(services.begin(), services.end(), service) == services.end()) continue;
      ProcessSpec p;
      p.name = id + "/" + service;
      p.robot_id = id;
      p.service = service;
      p.executable = find_executable(dirs_for(service), executable_name(service));
      p.arguments = {"--config", request.config_path, "--robot", id};
      p.arguments.insert(p.arguments.end(), request.extra_arguments.begin(), request.extra_arguments.end());
      if (p.executable.empty()) {
        plan.missing.push_back(executable_name(service) + " (for " + p.name + ") not found in " + joined(dirs_for(service)));
      }
      plan.processes.push_back(std::move(p));
    }
  }
  // In fast mode the station runs inside the composed process (inproc reaches no other process).
  if (request.compose_executable.empty() && std::find(services.begin(), services.end(), "station") != services.end()) {
    ProcessSpec p;
    p.name = std::string(core::kStationId);
    p.robot_id = std::string(core::kStationId);
    p.service = "station";
    p.is_station = true;
    p.executable = find_executable(dirs_for("station"), executable_name("station"));
    p.arguments = {"--config", request.config_path};
    p.arguments.insert(p.arguments.end(), request.extra_arguments.begin(), request.extra_arguments.end());
    p.ends_launch = true;
    if (!p.executable.empty()) {
      plan.processes.push_back(std::move(p));
    } else if (!station_optional) {
      plan.missing.push_back(executable_name("station") + " (for the station) not found in " + joined(dirs_for("station")));
    }
  }
  const bool has_station = std::any_of(plan.processes.begin(), plan.processes.end(),
                                       [](const ProcessSpec& p) { return p.is_station; });
  if (!request.compose_executable.empty() && !has_station) plan.processes.front().ends_launch = true;
  return plan;
}

}  // namespace hexplore::launcher
