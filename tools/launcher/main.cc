// hexplore_launch --config TEAM.yaml [--bin-dir DIR] [--robots id,id] [--services sim,mapping,...]
//                 [--log-dir DIR] [--exit-on-failure] [--grace-s S] [--child-args "ARGS"]
//                 [--compose [EXE]]
// Starts every service of every robot of the team (and the station when it is built) as
// separate processes on this machine; exits with the station's code when the station ends the
// mission, or on Ctrl-C after stopping everything. --compose (fast mode) runs every service of
// the team in one process instead: EXE (default hexplore_team) --config FILE --robot A --robot B.
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/core/config_error.h"
#include "common/core/team_config.h"
#include "common/service/team_keys.h"
#include "tools/launcher/launch_plan.h"
#include "tools/launcher/supervisor.h"

namespace {

constexpr const char* kUsage =
    "usage: hexplore_launch --config TEAM.yaml [--bin-dir DIR]... [--robots ID,ID] [--services "
    "sim,mapping,hlmap,planning,safety,station] [--log-dir DIR] [--exit-on-failure] [--grace-s SECONDS] "
    "[--child-args \"--log-level debug ...\"] [--compose [EXE]]";

}  // namespace

int main(int argc, char** argv) {
  using namespace hexplore;
  launcher::LaunchRequest request;
  launcher::SupervisorOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string flag = argv[i];
      if (flag == "--help" || flag == "-h") {
        std::cout << kUsage << "\n";
        return 0;
      }
      if (flag == "--exit-on-failure") {
        options.exit_on_failure = true;
        continue;
      }
      if (flag == "--compose") {
        request.compose_executable = "hexplore_team";
        if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) request.compose_executable = argv[++i];
        continue;
      }
      if (i + 1 >= argc) throw std::invalid_argument("missing value after " + flag);
      const std::string value = argv[++i];
      if (flag == "--config") {
        request.config_path = value;
      } else if (flag == "--bin-dir") {
        request.bin_dirs.push_back(value);
      } else if (flag == "--robots") {
        request.robots = launcher::split_list(value);
      } else if (flag == "--services") {
        request.services = launcher::split_list(value);
      } else if (flag == "--log-dir") {
        options.log_dir = value;
      } else if (flag == "--grace-s") {
        size_t used = 0;
        options.grace_s = std::stod(value, &used);
        if (used != value.size() || !(options.grace_s >= 0.0)) throw std::invalid_argument("--grace-s expects seconds >= 0");
      } else if (flag == "--child-args") {
        std::istringstream words(value);
        for (std::string w; words >> w;) request.extra_arguments.push_back(w);
      } else {
        throw std::invalid_argument("unknown option " + flag);
      }
    }
    if (request.config_path.empty()) throw std::invalid_argument("missing --config TEAM.yaml");
  } catch (const std::exception& e) {
    std::cerr << "hexplore_launch: " << e.what() << "\n" << kUsage << "\n";
    return 2;
  }

  launcher::LaunchPlan plan;
  try {
    const core::TeamConfig team = core::load_team_config(request.config_path);
    plan = launcher::plan_launch(team, request, argv[0]);
    // Authenticated links need every member's keys before the first process starts: made here
    // when missing (kept when present, so a running team's keys stay valid), as hexplore_keys would.
    const bool processes = request.compose_executable.empty() && team.transport.scheme == "tcp";
    if (processes && !team.transport.curve_keys_dir.empty()) {
      if (const int made = service::make_missing_team_keys(team))
        std::cerr << "hexplore_launch: made " << made << " CURVE key pair(s) in " << team.transport.curve_keys_dir << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "hexplore_launch: error: " << e.what() << "\n";
    return 2;
  }
  if (!plan.missing.empty()) {
    for (const auto& m : plan.missing) std::cerr << "hexplore_launch: error: missing executable " << m << "\n";
    std::cerr << "hexplore_launch: build the missing services, point --bin-dir at them, or leave them out with --services\n";
    return 2;
  }
  if (plan.processes.empty()) {
    std::cerr << "hexplore_launch: error: nothing to start\n";
    return 2;
  }
  try {
    launcher::Supervisor supervisor(options);
    supervisor.start(plan.processes);
    return supervisor.run();
  } catch (const std::exception& e) {
    std::cerr << "hexplore_launch: error: " << e.what() << "\n";
    return 1;
  }
}
