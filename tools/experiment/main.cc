// hexplore_experiment: one mission per seed in the reproducible fast mode (every service of
// the team in this process, in lockstep on sim time), then the mean and spread of the results.
//   hexplore_experiment --config TEAM.yaml --seeds 1,2,3|1-5 [--results DIR] [--planner NAME]
//                       [--time-limit-s S] [--robot ID ...] [--log-level L] [--<service option> <value> ...]
// Each seed writes DIR/seed-<n>/ (the station's results folder); DIR/summary.json holds the
// summary. The seed draws LiDAR noise, the GA's random choices and, for the built-in procedural
// scenes, the scene's details.
// The comparison: --planners a,b,c runs every planner's seeds into DIR/<planner>/ (as above;
// --trace-dir T: traces into T/<planner>/seed-<n>;
// --jobs N runs up to N planners at once, each as a child process logging to
// DIR/<planner>/experiment.log), then tools/report/compare_report.py writes DIR/comparison.*
// and DIR/figures/ (--report-script PATH names another script). Every seeds folder gets its
// figures from tools/report/run_report.py; --report false skips both.
// Beyond one machine: --emit-slurm DIR writes the same runs (planners x seeds) as a Slurm job
// array instead of running them, and --gather DIR writes the comparison of what the array's
// tasks left (tools/experiment/slurm_sweep.h).
// Exit: 0 all runs finished, 1 a run failed or was interrupted, 2 bad arguments or team file.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <map>
#include <optional>

#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/planning/planner_registry.h"
#include "common/service/option_catalogue.h"
#include "common/service/service.h"
#include "common/evaluation/report_script.h"
#include "common/evaluation/results_writer.h"
#include "services/station/station_service.h"
#include "tools/team/team_services.h"
#include "tools/experiment/experiment_args.h"
#include "tools/experiment/progress_line.h"
#include "tools/experiment/slurm_sweep.h"

namespace hexplore::experiment {
namespace {

enum class Outcome { kFinished, kFailed, kInterrupted };

// Runs one mission to its end; the station's record lands in `record` when it finished.
// `label` ("run 1/5 seed 3") names it on the progress line, drawn when stdout is a terminal.
Outcome run_one(const core::TeamConfig& team, const ExperimentArgs& args, const std::string& results_dir,
                const std::string& label, const sigset_t& stop_signals,
                std::optional<evaluation::ExperimentRecord>& record) {
  service::HostOptions options;
  options.compose = true;
  options.lockstep = true;
  options.metrics_port = 0;
  options.arguments = args.service_arguments;
  options.arguments["results"] = results_dir;
  options.arguments["report"] = "false";  // the figures of every seed are drawn together at the end
  // On a terminal the progress line replaces the station's lines; in a log (CI, a comparison's
  // child) the station says where the mission is once a minute of sim time, not every 5 s.
  const bool terminal = is_terminal(stdout);
  options.arguments.try_emplace("progress-period-s", terminal ? "0" : "60");
  // Each mission's planning traces in a folder of their own (DIR/seed-<n>), not on top of
  // the previous seed's.
  if (auto it = options.arguments.find("trace-dir"); it != options.arguments.end())
    it->second = (std::filesystem::path(it->second) / std::filesystem::path(results_dir).filename()).string();
  service::ServiceHost host(team, options);
  std::vector<std::string> robots = args.robots;
  if (robots.empty())
    for (const auto& r : team.robots) robots.push_back(r.id);
  for (const auto& robot : robots)
    for (const auto& factory : team::robot_services()) host.add(factory(), robot);
  auto station_owned = std::make_unique<station_service::StationService>();
  station_service::StationService* station = station_owned.get();
  host.add(std::move(station_owned), std::string(core::kStationId));
  host.start();  // throws core::ConfigError for a team the services refuse

  bool interrupted = false;
  const timespec tick{0, 100'000'000};
  std::optional<ProgressLine> progress;
  if (terminal) progress.emplace(stdout, label, team.time_limit_s);
  while (!host.any_finished()) {
    const int signal = sigtimedwait(&stop_signals, nullptr, &tick);
    if (signal == SIGINT || signal == SIGTERM) {
      interrupted = true;
      break;
    }
    if (progress) progress->update(station->progress());
  }
  progress.reset();  // ends the line before anything else is printed
  host.stop();
  host.wait();
  if (interrupted) return Outcome::kInterrupted;
  if (host.failed() || station->result() == nullptr) return Outcome::kFailed;
  record = *station->result();
  return Outcome::kFinished;
}

// Every seed of one planner (`planner` overrides params.planner when set) into `dir`:
// dir/seed-<n>/ and dir/summary.json. Returns the exit code (0, 1, or 2 for a team the
// services refuse).
// Runs a report script of tools/report on `folder`; says why when it cannot (the runs stand).
void run_report(const std::string& script, const std::string& folder) {
  std::printf("[experiment] report: %s %s\n", script.c_str(), folder.c_str());
  std::fflush(stdout);
  if (const auto why_not = evaluation::run_report_script(script, folder))
    std::printf("[experiment] no report for %s: %s; the runs themselves are there\n", folder.c_str(), why_not->c_str());
}

int run_seeds(const core::TeamConfig& base, const ExperimentArgs& args, const std::string& results_dir,
              const std::optional<std::string>& planner, const sigset_t& stop_signals) {
  std::vector<evaluation::ExperimentRecord> records;
  int exit_code = 0;
  for (size_t i = 0; i < args.seeds.size(); ++i) {
    core::TeamConfig team = base;
    team.params.seed = args.seeds[i];
    if (planner) team.params.planner = *planner;
    if (args.time_limit_s) team.time_limit_s = *args.time_limit_s;
    const std::string dir = (std::filesystem::path(results_dir) / ("seed-" + std::to_string(team.params.seed))).string();
    std::printf("[experiment] run %zu/%zu: seed %llu -> %s\n", i + 1, args.seeds.size(),
                static_cast<unsigned long long>(team.params.seed), dir.c_str());
    std::fflush(stdout);
    const std::string label = "run " + std::to_string(i + 1) + "/" + std::to_string(args.seeds.size()) + " seed " +
                              std::to_string(team.params.seed);
    std::optional<evaluation::ExperimentRecord> record;
    Outcome outcome;
    try {
      outcome = run_one(team, args, dir, label, stop_signals, record);
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
  const std::string summary = evaluation::multi_run_summary_json(records);
  const auto path = std::filesystem::path(results_dir) / "summary.json";
  std::filesystem::create_directories(results_dir);
  std::ofstream(path) << summary;
  std::printf("[experiment] %zu runs; summary in %s\n%s", records.size(), path.c_str(), summary.c_str());
  // Each seed's figures and report.md, and completeness over the seeds (mean and spread).
  if (args.report) run_report(evaluation::report_script_path("run_report.py"), results_dir);
  return exit_code;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ",") + s;
  return out;
}

// One planner's seeds as a child process (this executable with --planner), output to its log.
pid_t spawn_planner(const ExperimentArgs& args, const std::string& planner, const std::string& dir) {
  std::vector<std::string> argv = {"/proc/self/exe", "--config", args.config, "--planner", planner, "--results", dir,
                                   "--log-level", args.log_level};
  std::string seeds;
  for (uint64_t s : args.seeds) seeds += (seeds.empty() ? "" : ",") + std::to_string(s);
  argv.insert(argv.end(), {"--seeds", seeds, "--report", args.report ? "true" : "false"});
  if (args.time_limit_s) argv.insert(argv.end(), {"--time-limit-s", std::to_string(*args.time_limit_s)});
  for (const auto& r : args.robots) argv.insert(argv.end(), {"--robot", r});
  for (const auto& [k, v] : args.service_arguments) argv.insert(argv.end(), {"--" + k, v});
  std::filesystem::create_directories(dir);
  const std::string log = (std::filesystem::path(dir) / "experiment.log").string();
  const pid_t pid = fork();
  if (pid != 0) return pid;  // parent (or -1)
  FILE* out = std::freopen(log.c_str(), "w", stdout);
  if (out) dup2(fileno(stdout), fileno(stderr));
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  execv("/proc/self/exe", raw.data());
  std::perror("hexplore_experiment: exec");
  _exit(127);
}


// One planner's arguments in a comparison: its planning traces under TRACE_DIR/<planner>/, as
// its results are under DIR/<planner>/ (planners run side by side would write the same files).
ExperimentArgs for_planner(const ExperimentArgs& args, const std::string& planner) {
  ExperimentArgs out = args;
  if (auto it = out.service_arguments.find("trace-dir"); it != out.service_arguments.end())
    it->second = (std::filesystem::path(it->second) / planner).string();
  return out;
}

// --planners: each planner's seeds into results_dir/<planner>/, then the report.
int run_comparison(const core::TeamConfig& base, const ExperimentArgs& args, const sigset_t& stop_signals) {
  namespace fs = std::filesystem;
  fs::create_directories(args.results_dir);
  std::ofstream(fs::path(args.results_dir) / "planners.txt") << join(args.planners) << "\n";
  int exit_code = 0;
  if (args.jobs <= 1) {
    for (const auto& planner : args.planners) {
      std::printf("[experiment] planner %s\n", planner.c_str());
      const int code = run_seeds(base, for_planner(args, planner), (fs::path(args.results_dir) / planner).string(), planner,
                                 stop_signals);
      if (code == 2) return 2;
      exit_code = std::max(exit_code, code);
    }
  } else {
    std::map<pid_t, std::string> running;
    size_t next = 0;
    bool interrupted = false;
    const timespec tick{0, 200'000'000};
    while (next < args.planners.size() || !running.empty()) {
      while (!interrupted && next < args.planners.size() && int(running.size()) < args.jobs) {
        const std::string& planner = args.planners[next++];
        const std::string dir = (fs::path(args.results_dir) / planner).string();
        const pid_t pid = spawn_planner(for_planner(args, planner), planner, dir);
        if (pid < 0) {
          std::printf("[experiment] could not start the runs of %s\n", planner.c_str());
          exit_code = 1;
          continue;
        }
        running[pid] = planner;
        std::printf("[experiment] planner %s: %zu seeds in a child process (log: %s/experiment.log)\n",
                    planner.c_str(), args.seeds.size(), dir.c_str());
        std::fflush(stdout);
      }
      const int signal = sigtimedwait(&stop_signals, nullptr, &tick);
      if ((signal == SIGINT || signal == SIGTERM) && !interrupted) {
        interrupted = true;
        exit_code = 1;
        for (const auto& [pid, _] : running) kill(pid, SIGTERM);
      }
      int status = 0;
      for (pid_t pid; (pid = waitpid(-1, &status, WNOHANG)) > 0;) {
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
        std::printf("[experiment] planner %s finished (exit %d)\n", it->second.c_str(), code);
        std::fflush(stdout);
        if (code == 2) exit_code = 2;
        else exit_code = std::max(exit_code, code);
        running.erase(it);
      }
      if (interrupted && next < args.planners.size()) next = args.planners.size();
    }
    if (interrupted) {
      std::printf("[experiment] interrupted\n");
      return 1;
    }
  }
  if (args.report)
    run_report(args.report_script.value_or(evaluation::report_script_path("compare_report.py")), args.results_dir);
  return exit_code;
}

// --emit-slurm: the runs as a job array, nothing run here.
int emit_slurm(const ExperimentArgs& args) {
  const std::string script =
      write_slurm_sweep(args, std::filesystem::read_symlink("/proc/self/exe").string(), *args.emit_slurm);
  const auto runs = sweep_runs(args);
  std::printf("[experiment] %zu runs as a Slurm job array: %s (runs.tsv beside it)\n"
              "[experiment] submit: sbatch %s\n"
              "[experiment] when every task has ended: hexplore_experiment --gather %s\n",
              runs.size(), script.c_str(), script.c_str(), std::filesystem::absolute(*args.emit_slurm).c_str());
  return 0;
}

// --gather: every run of the sweep must have left its summary; then the figures and the
// comparison, as --planners writes them on one machine.
int gather(const ExperimentArgs& args) {
  const SweepStatus sweep = read_sweep(*args.gather);
  std::printf("[experiment] %zu of %zu runs of %s have results in %s\n", sweep.done.size(),
              sweep.done.size() + sweep.missing.size(), args.gather->c_str(), sweep.results_dir.c_str());
  for (const auto& run : sweep.missing)
    std::printf("[experiment] missing: planner %s, seed %llu (its task's log is in %s/logs/)\n",
                run.planner.empty() ? "(team file's)" : run.planner.c_str(), static_cast<unsigned long long>(run.seed),
                args.gather->c_str());
  if (sweep.done.empty()) return 1;
  const bool comparison = !(sweep.planners.size() == 1 && sweep.planners[0].empty());
  if (comparison) {
    std::ofstream(std::filesystem::path(sweep.results_dir) / "planners.txt") << join(sweep.planners) << "\n";
    if (args.report) {
      for (const auto& planner : sweep.planners)
        run_report(evaluation::report_script_path("run_report.py"), (std::filesystem::path(sweep.results_dir) / planner).string());
      run_report(args.report_script.value_or(evaluation::report_script_path("compare_report.py")), sweep.results_dir);
    }
  } else if (args.report) {
    run_report(evaluation::report_script_path("run_report.py"), sweep.results_dir);
  }
  return sweep.missing.empty() ? 0 : 1;
}

int run(int argc, char** argv) {
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  constexpr const char* kUsage =
      "usage: hexplore_experiment --config TEAM.yaml --seeds 1,2,3|1-5 [--results DIR] "
      "[--planner NAME | --planners A,B,C [--jobs N] [--report true|false] [--report-script PATH]] "
      "[--time-limit-s S] [--robot ID ...] [--log-level L] [--emit-slurm DIR] [--<service option> <value> ...]\n"
      "       hexplore_experiment --gather DIR   (the comparison of a sweep's results; DIR as --emit-slurm wrote it)\n";
  ExperimentArgs args;
  core::TeamConfig base;
  try {
    args = parse_experiment_args(argc, argv);
    if (args.help) {
      std::cout << kUsage << "\nservice options (each read by the services named):\n" << service::service_options_help();
      return 0;
    }
    core::LogLevel level;
    if (!core::parse_log_level(args.log_level, level))
      throw std::invalid_argument("--log-level must be debug, info, warn or error, got '" + args.log_level + "'");
    core::set_log_level(level);
    if (!args.gather) {  // a sweep folder holds its planners and team file already
      const planning::PlannerRegistry registry = planning::PlannerRegistry::builtin();
      std::vector<std::string> wanted = args.planners;
      if (args.planner) wanted.push_back(*args.planner);
      for (const auto& name : wanted)
        if (!registry.contains(name)) registry.create(name);  // throws, listing the known planners
      base = core::load_team_config(args.config);
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const core::ConfigError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  if (args.gather || args.emit_slurm) {
    try {
      return args.gather ? gather(args) : emit_slurm(args);
    } catch (const std::exception& e) {  // a sweep folder that cannot be written or read
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    }
  }
  if (!args.planners.empty()) return run_comparison(base, args, stop_signals);
  return run_seeds(base, args, args.results_dir, args.planner, stop_signals);
}

}  // namespace
}  // namespace hexplore::experiment

int main(int argc, char** argv) { return hexplore::experiment::run(argc, argv); }
