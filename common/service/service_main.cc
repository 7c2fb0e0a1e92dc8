// Command-line entry points: parse flags, load the team file, host the service(s), and turn
// SIGINT/SIGTERM into a clean stop. Signals are blocked in every thread and taken by the main
// thread with sigtimedwait, so no handler ever runs inside ZeroMQ or protobuf code.
#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/service/option_catalogue.h"
#include "common/service/service.h"

namespace hexplore::service {
namespace {

struct CommandLine {
  std::string config;
  std::vector<std::string> robots;
  std::string log_level = "info";
  std::optional<int> metrics_port;
  int status_period_ms = 1000;
  transport::FaultInjection faults;
  std::map<std::string, std::string> arguments;
};

constexpr const char* kUsage =
    "usage: %s --config TEAM.yaml --robot ID [--log-level debug|info|warn|error] [--metrics-port N|-1] "
    "[--status-period-ms N] [--fault-drop F] [--fault-delay-ms N] [--fault-topics P,P] [--fault-seed N] "
    "[--<option> <value> ...]";

// Throws std::invalid_argument with a one-line message.
CommandLine parse(int argc, char** argv, bool many_robots) {
  CommandLine cl;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag.rfind("--", 0) != 0 || flag.size() < 3)
      throw std::invalid_argument("unexpected argument '" + flag + "'");
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + flag);
    const std::string value = argv[++i];
    auto to_int = [&](const std::string& what) {
      try {
        size_t used = 0;
        const int v = std::stoi(value, &used);
        if (used != value.size()) throw std::invalid_argument(value);
        return v;
      } catch (const std::exception&) {
        throw std::invalid_argument(what + " expects an integer, got '" + value + "'");
      }
    };
    if (flag == "--config") {
      cl.config = value;
    } else if (flag == "--robot") {
      if (!many_robots && !cl.robots.empty()) throw std::invalid_argument("--robot given twice");
      cl.robots.push_back(value);
    } else if (flag == "--log-level") {
      cl.log_level = value;
    } else if (flag == "--metrics-port") {
      cl.metrics_port = to_int("--metrics-port");
      if (*cl.metrics_port < -1 || *cl.metrics_port > 65535)
        throw std::invalid_argument("--metrics-port must be -1 (any free port), 0 (off) or a port number");
    } else if (flag == "--status-period-ms") {
      cl.status_period_ms = to_int("--status-period-ms");
      if (cl.status_period_ms <= 0) throw std::invalid_argument("--status-period-ms must be > 0");
    } else if (flag == "--fault-drop") {
      try {
        cl.faults.drop_fraction = std::stod(value);
      } catch (const std::exception&) {
        cl.faults.drop_fraction = -1.0;
      }
      if (!(cl.faults.drop_fraction >= 0.0 && cl.faults.drop_fraction <= 1.0))
        throw std::invalid_argument("--fault-drop expects a fraction in [0, 1], got '" + value + "'");
    } else if (flag == "--fault-delay-ms") {
      cl.faults.delay = std::chrono::milliseconds(to_int("--fault-delay-ms"));
      if (cl.faults.delay.count() < 0) throw std::invalid_argument("--fault-delay-ms must be >= 0");
    } else if (flag == "--fault-topics") {
      for (size_t start = 0; start <= value.size();) {
        const size_t comma = std::min(value.find(',', start), value.size());
        if (comma > start) cl.faults.topic_prefixes.push_back(value.substr(start, comma - start));
        start = comma + 1;
      }
    } else if (flag == "--fault-seed") {
      cl.faults.seed = static_cast<uint64_t>(to_int("--fault-seed"));
    } else {
      cl.arguments[flag.substr(2)] = value;
    }
  }
  if (cl.config.empty()) throw std::invalid_argument("missing --config TEAM.yaml");
  if (cl.robots.empty()) throw std::invalid_argument("missing --robot ID");
  core::LogLevel level;
  if (!core::parse_log_level(cl.log_level, level))
    throw std::invalid_argument("--log-level must be debug, info, warn or error, got '" + cl.log_level + "'");
  core::set_log_level(level);
  return cl;
}

// `station`, when given, adds one station service; then the process ends as soon as any of
// its services ends (the station's end is the mission's end; any other is a failure).
int run(int argc, char** argv, const std::vector<ServiceFactory>& factories, bool compose,
        const ServiceFactory* station = nullptr) {
  // Block the stop signals before any thread exists, so every thread (ZeroMQ's included) inherits the mask.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  const std::string program = argc > 0 ? argv[0] : "service";
  char usage[512];
  std::snprintf(usage, sizeof(usage), kUsage, program.c_str());
  CommandLine cl;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << usage << "\n\nservice options (each read by the services named):\n" << service_options_help();
      return 0;
    }
  }
  try {
    cl = parse(argc, argv, compose);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n" << usage << "\n";
    return 2;
  }
  std::unique_ptr<ServiceHost> host;
  try {
    HostOptions options;
    options.metrics_port = cl.metrics_port;
    options.status_period = std::chrono::milliseconds(cl.status_period_ms);
    options.compose = compose;
    options.lockstep = station != nullptr;  // the one-process team is the reproducible fast mode
    options.arguments = cl.arguments;
    options.publisher_faults = cl.faults;
    host = std::make_unique<ServiceHost>(core::load_team_config(cl.config), options);
    for (const auto& robot : cl.robots)
      for (const auto& factory : factories) host->add(factory(), robot);
    if (station) host->add((*station)(), std::string(core::kStationId));
    host->start();
  } catch (const core::ConfigError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }

  // Wait for a stop signal, or for every service to end on its own.
  timespec tick{0, 100'000'000};
  while (!host->finished()) {
    if (station && host->any_finished()) {
      host->stop();
      break;
    }
    const int signal = sigtimedwait(&stop_signals, nullptr, &tick);
    if (signal == SIGINT || signal == SIGTERM) {
      core::LogLine(core::LogLevel::kInfo, "service") << "received " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                                                       << ", stopping";
      host->stop();
      break;
    }
  }
  host->wait();
  const bool failed = host->failed();
  host.reset();  // closes the transport; queued messages get up to linger_ms to leave
  return failed ? 1 : 0;
}

}  // namespace

int run_service_main(int argc, char** argv, const ServiceFactory& factory) {
  return run(argc, argv, {factory}, false);
}

int run_composition_main(int argc, char** argv, const std::vector<ServiceFactory>& factories) {
  return run(argc, argv, factories, true);
}

int run_team_main(int argc, char** argv, const std::vector<ServiceFactory>& robot_factories,
                  const ServiceFactory& station) {
  return run(argc, argv, robot_factories, true, &station);
}

}  // namespace hexplore::service
