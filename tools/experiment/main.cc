// hexplore_experiment: one mission per seed in the reproducible fast mode (every service of
// the team in this process, in lockstep on sim time), then the mean and spread of the results.
//   hexplore_experiment --config TEAM.yaml --seeds 1,2,3|1-5 [--results DIR] [--planner NAME]
//                       [--robot ID ...] [--log-level L] [--<service option> <value> ...]
// Each seed writes DIR/seed-<n>/ (the station's results folder); DIR/summary.json holds the
// summary. The seed draws LiDAR noise, the GA's random choices and, for the built-in procedural
// scenes, the scene's details. Exit: 0 all runs finished, 1 a run failed or was interrupted,
// 2 bad arguments or team file.
#include <signal.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/service/service.h"
#include "common/station/results_writer.h"
#include "services/station/station_service.h"
#include "services/team/team_services.h"
#include "tools/experiment/experiment_args.h"

namespace hexplore::experiment {
namespace {

enum class Outcome { kFinished, kFailed, kInterrupted };

// Runs one mission to its end; the station's record lands in `record` when it finished.
Outcome run_one(const core::TeamConfig& team, const ExperimentArgs& args, const std::string& results_dir,
                const sigset_t& stop_signals, std::optional<station::ExperimentRecord>& record) {
  service::HostOptions options;
  options.compose = true;
  options.lockstep = true;
  options.metrics_port = 0;
  options.arguments = args.service_arguments;
  options.arguments["results"] = results_dir;
  service::ServiceHost host(team, options);
  std::vector<std::string> robots = args.robots;
  if (robots.empty())
    for (const auto& r : team.robots) robots.push_back(r.id);
  for (const auto& robot : robots)
    for (const auto& factory : team::robot_services()) host.add(factory(), robot);
  auto station_owned = std::make_unique<station::StationService>();
  station::StationService* station = station_owned.get();
  host.add(std::move(station_owned), std::string(core::kStationId));
  host.start();  // throws core::ConfigError for a team the services refuse

  bool interrupted = false;
  const timespec tick{0, 100'000'000};
  while (!host.any_finished()) {
    const int signal = sigtimedwait(&stop_signals, nullptr, &tick);
    if (signal == SIGINT || signal == SIGTERM) {
      interrupted = true;
      break;
    }
  }
  host.stop();
  host.wait();
  if (interrupted) return Outcome::kInterrupted;
  if (host.failed() || station->result() == nullptr) return Outcome::kFailed;
  record = *station->result();
  return Outcome::kFinished;
}

int run(int argc, char** argv) {
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  ExperimentArgs args;
  core::TeamConfig base;
  try {
    args = parse_experiment_args(argc, argv);
    core::LogLevel level;
    if (!core::parse_log_level(args.log_level, level))
      throw std::invalid_argument("--log-level must be debug, info, warn or error, got '" + args.log_level + "'");
    core::set_log_level(level);
    base = core::load_team_config(args.config);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n"
              << "usage: hexplore_experiment --config TEAM.yaml --seeds 1,2,3|1-5 [--results DIR] [--planner NAME] "
                 "[--robot ID ...] [--log-level L] [--<service option> <value> ...]\n";
    return 2;
  } catch (const core::ConfigError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }

  std::vector<station::ExperimentRecord> records;
  int exit_code = 0;
  for (size_t i = 0; i < args.seeds.size(); ++i) {
    core::TeamConfig team = base;
    team.params.seed = args.seeds[i];
    if (args.planner) team.params.planner = *args.planner;
    const std::string dir = (std::filesystem::path(args.results_dir) / ("seed-" + std::to_string(team.params.seed))).string();
    std::printf("[experiment] run %zu/%zu: seed %llu -> %s\n", i + 1, args.seeds.size(),
                static_cast<unsigned long long>(team.params.seed), dir.c_str());
    std::fflush(stdout);
    std::optional<station::ExperimentRecord> record;
    Outcome outcome;
    try {
      outcome = run_one(team, args, dir, stop_signals, record);
    } catch (const core::ConfigError& e) {
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "error: seed " << team.params.seed << ": " << e.what() << "\n";
      outcome = Outcome::kFailed;
    }
    if (outcome == Outcome::kInterrupted) {
      std::printf("[experiment] interrupted; summarising the %zu finished runs\n", records.size());
      exit_code = 1;
      break;
    }
    if (outcome == Outcome::kFailed) {
      std::printf("[experiment] seed %llu failed (see the log above); it is left out of the summary\n",
                  static_cast<unsigned long long>(team.params.seed));
      exit_code = 1;
      continue;
    }
    std::printf("[experiment] seed %llu: %s after %.1f s sim time (%.1f s wall), completeness %.1f%%\n",
                static_cast<unsigned long long>(team.params.seed), record->end_reason.c_str(),
                record->exploration_time_s, record->wall_time_s, 100.0 * record->final_team_completeness());
    std::fflush(stdout);
    records.push_back(std::move(*record));
  }
  if (records.empty()) {
    std::cerr << "error: no run finished; no summary written\n";
    return 1;
  }
  const std::string summary = station::multi_run_summary_json(records);
  const auto path = std::filesystem::path(args.results_dir) / "summary.json";
  std::filesystem::create_directories(args.results_dir);
  std::ofstream(path) << summary;
  std::printf("[experiment] %zu runs; summary in %s\n%s", records.size(), path.c_str(), summary.c_str());
  return exit_code;
}

}  // namespace
}  // namespace hexplore::experiment

int main(int argc, char** argv) { return hexplore::experiment::run(argc, argv); }
