// Service base: config errors and their exit code, status, metrics, SIGTERM with queued
// messages (the echo_service helper process over tcp), and composition over inproc.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "common/core/config_error.h"
#include "common/service/service.h"
#include "tests/service/echo_service.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_ports.h"
#include "tests/transport/child_process.h"

namespace hexplore::service {
namespace {

using namespace std::chrono_literals;
using testing::ChildProcess;
using testing::EchoService;

// This binary's files (team files its service processes read), removed when it exits.
const hexplore::testing::ScratchDir& scratch() {
  static const hexplore::testing::ScratchDir dir("service_test");
  return dir;
}

// A team file in the test's temp dir, on a random block of ports so parallel tests don't collide.
std::string write_team(const std::string& name, const std::string& extra = "", int* base_port_out = nullptr) {
  const int base_port = hexplore::testing::random_base_port();
  if (base_port_out) *base_port_out = base_port;
  const std::string path = scratch().file(name + ".yaml");
  std::ofstream out(path);
  out << "species:\n  - builtin: SLUGCAT\nrobots:\n  - {id: a, species: SLUGCAT}\n  - {id: b, species: SLUGCAT}\n"
      << "transport:\n  scheme: tcp\n  base_port: " << base_port << "\n"
      << extra;
  return path;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

// Runs echo_service with `args`, expects exit code 2 and a single "error: ..." line.
std::string expect_config_error(std::vector<std::string> args) {
  args.insert(args.begin(), ECHO_SERVICE_PATH);
  ChildProcess child(args);
  const auto code = child.wait_exit(10s);
  EXPECT_EQ(code, 2) << child.output();
  const auto lines = lines_of(child.output());
  EXPECT_EQ(lines.size(), 1u) << child.output();
  if (lines.empty()) return "";
  EXPECT_EQ(lines[0].rfind("error: ", 0), 0u) << lines[0];
  return lines[0];
}

TEST(ServiceMain, MissingConfigFileIsOneClearError) {
  const std::string line = expect_config_error({"--config", "/nonexistent/team.yaml", "--robot", "a"});
  EXPECT_NE(line.find("/nonexistent/team.yaml"), std::string::npos) << line;
}

TEST(ServiceMain, BadValueNamesFileAndKey) {
  const std::string path = write_team("bad_value");
  std::ofstream(path, std::ios::app) << "time_limit_s: soon\n";
  const std::string line = expect_config_error({"--config", path, "--robot", "a"});
  EXPECT_NE(line.find(path), std::string::npos) << line;
  EXPECT_NE(line.find("time_limit_s"), std::string::npos) << line;
}

TEST(ServiceMain, BrokenYamlIsOneClearError) {
  const std::string path = scratch().file("broken.yaml");
  std::ofstream(path) << "robots: [ {id: a\n";
  const std::string line = expect_config_error({"--config", path, "--robot", "a"});
  EXPECT_NE(line.find(path), std::string::npos) << line;
}

TEST(ServiceMain, UnknownRobotIsOneClearError) {
  const std::string path = write_team("unknown_robot");
  const std::string line = expect_config_error({"--config", path, "--robot", "zz"});
  EXPECT_NE(line.find("unknown robot id 'zz'"), std::string::npos) << line;
  EXPECT_NE(line.find("known: a, b"), std::string::npos) << line;
}

TEST(ServiceMain, MissingRobotFlag) {
  ChildProcess child({ECHO_SERVICE_PATH, "--config", write_team("no_robot")});
  EXPECT_EQ(child.wait_exit(10s), 2);
  const auto lines = lines_of(child.output());
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "error: missing --robot ID");
}

TEST(ServiceMain, StatusMetricsAndSigtermWithoutLostMessages) {
  const std::string path = write_team("sigterm");
  const core::TeamConfig team = core::load_team_config(path);
  ChildProcess child({ECHO_SERVICE_PATH, "--config", path, "--robot", "a", "--metrics-port", "-1",
                      "--status-period-ms", "100"});
  const auto metrics_line = child.wait_for_line("serving /metrics on port ", 10s);
  ASSERT_TRUE(metrics_line) << child.output();
  const int metrics_port = std::stoi(metrics_line->substr(metrics_line->rfind(' ') + 1));

  transport::Context context;
  transport::Accounting accounting("b", "test");
  transport::Subscriber subscriber(context, {}, &accounting);
  subscriber.connect(core::connect_endpoint(team, "a", core::ServiceKind::kMapping, core::SocketRole::kPublish));
  std::vector<v1::ServiceState> states;
  uint64_t received = 0, last = 0;
  subscriber.on<v1::ServiceStatus>("robot/a/status", [&](const transport::Received<v1::ServiceStatus>& m) {
    EXPECT_EQ(m.message.service(), "mapping");
    EXPECT_EQ(m.header.species(), "SLUGCAT");
    states.push_back(m.message.state());
  });
  subscriber.on<v1::TestPayload>("robot/a/burst", [&](const transport::Received<v1::TestPayload>& m) {
    ++received;
    last = m.message.counter();
  });
  transport::Requester requester(context, transport::Identity{"b", "SLUGCAT", "test"},
                                 core::connect_endpoint(team, "a", core::ServiceKind::kMapping, core::SocketRole::kRequest),
                                 {}, &accounting, "a");
  transport::EventLoop loop;
  loop.add(subscriber);
  loop.add(requester);
  ASSERT_TRUE(loop.run_until([&] { return !states.empty(); }, 10s)) << child.output();
  EXPECT_EQ(states.back(), v1::SERVICE_STATE_RUNNING);

  // /metrics of the service carries transport and process families with service labels.
  const std::string file = ::testing::TempDir() + "/service_metrics_" + std::to_string(getpid());
  ASSERT_EQ(std::system(("curl -s -f -m 5 -o '" + file + "' http://127.0.0.1:" + std::to_string(metrics_port) + "/metrics").c_str()), 0);
  std::stringstream body;
  body << std::ifstream(file).rdbuf();
  EXPECT_NE(body.str().find("hexplore_process_uptime_seconds{robot=\"a\",service=\"mapping\"}"), std::string::npos) << body.str();
  EXPECT_NE(body.str().find("hexplore_process_cpu_seconds_total{robot=\"a\",service=\"mapping\"}"), std::string::npos);
  EXPECT_NE(body.str().find("hexplore_transport_sent_messages_total{peer=\"broadcast\",robot=\"a\",service=\"mapping\",topic=\"robot/a/status\"}"),
            std::string::npos);

  constexpr uint64_t kBurst = 4000;
  v1::TestPayload request;
  request.set_counter(kBurst);
  request.set_blob(std::string(2000, 'q'));
  requester.request<v1::TestPayload, v1::TestPayload>(request, [](const transport::Received<v1::TestPayload>*) {}, 5s);
  bool sent = false;
  ASSERT_TRUE(loop.run_until([&] { return sent = sent || child.wait_for_line("burst-sent 4000", 0ms); }, 10s));
  child.signal(SIGTERM);
  EXPECT_TRUE(loop.run_until([&] { return received == kBurst && !states.empty() && states.back() == v1::SERVICE_STATE_STOPPING; }, 15s))
      << received;
  EXPECT_EQ(last, kBurst);
  EXPECT_EQ(child.wait_exit(10s), 0);
  EXPECT_NE(child.output().find("shutdown mapping"), std::string::npos);
  EXPECT_NE(child.output().find("received SIGTERM, stopping"), std::string::npos);
}

TEST(ServiceHost, ComposesServicesOverInproc) {
  core::TeamConfig team = core::load_team_config(write_team("compose"));
  HostOptions options;
  options.compose = true;
  options.metrics_port = 0;
  options.status_period = 50ms;
  ServiceHost host(team, options);
  EXPECT_EQ(host.team().transport.scheme, "inproc");
  auto a = std::make_unique<EchoService>(core::ServiceKind::kHlmap, 10ms);
  auto b = std::make_unique<EchoService>(core::ServiceKind::kHlmap, 10ms);
  EchoService* a_raw = a.get();
  EchoService* b_raw = b.get();
  host.add(std::move(a), "a");
  host.add(std::move(b), "b");
  host.start();
  EXPECT_TRUE(a_raw->setup_done && b_raw->setup_done);
  const auto end = std::chrono::steady_clock::now() + 10s;
  while ((a_raw->teammate_messages < 5 || b_raw->teammate_messages < 5) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(5ms);
  EXPECT_GE(a_raw->teammate_messages, 5u);
  EXPECT_GE(b_raw->teammate_messages, 5u);
  host.stop();
  host.wait();
  EXPECT_TRUE(host.finished());
}

TEST(ServiceMain, AServiceThatThrowsEndsTheProcessWithExitCode1) {
  ChildProcess child({ECHO_SERVICE_PATH, "--config", write_team("throwing"), "--robot", "b", "--throw-after-ms", "50"});
  EXPECT_EQ(child.wait_exit(10s), 1);
  EXPECT_NE(child.output().find("stopped by an exception: echo service asked to fail"), std::string::npos)
      << child.output();
}

TEST(ServiceMain, ComposedProcessWithFaultInjection) {
  const std::string path = write_team("composed_main");
  ChildProcess child({ECHO_SERVICE_PATH, "--composed", "yes", "--config", path, "--robot", "a", "--robot", "b",
                      "--metrics-port", "-1", "--fault-drop", "0.5", "--fault-topics", "team/echo", "--fault-seed", "3"});
  const auto metrics_line = child.wait_for_line("serving /metrics on port ", 10s);
  ASSERT_TRUE(metrics_line) << child.output();
  const std::string url = "http://127.0.0.1:" + metrics_line->substr(metrics_line->rfind(' ') + 1) + "/metrics";
  const std::string file = ::testing::TempDir() + "/composed_metrics_" + std::to_string(getpid());
  const std::string received = "hexplore_transport_received_messages_total{peer=\"b\",robot=\"a\",service=\"hlmap\",topic=\"team/echo\"}";
  const std::string dropped = "hexplore_transport_dropped_total{reason=\"fault_injected\",robot=\"b\",service=\"planning\",topic=\"team/echo\"}";
  std::string body;
  for (int i = 0; i < 100; ++i) {  // the services publish every 20 ms; poll until both lines exist
    ASSERT_EQ(std::system(("curl -s -f -m 5 -o '" + file + "' " + url).c_str()), 0);
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    body = text.str();
    if (body.find(received) != std::string::npos && body.find(dropped) != std::string::npos) break;
    std::this_thread::sleep_for(50ms);
  }
  EXPECT_NE(body.find(received), std::string::npos) << body;
  EXPECT_NE(body.find(dropped), std::string::npos) << body;
  child.signal(SIGTERM);
  EXPECT_EQ(child.wait_exit(10s), 0);
  const std::string& out = child.output();
  size_t shutdowns = 0;
  for (size_t at = out.find("shutdown "); at != std::string::npos; at = out.find("shutdown ", at + 1)) ++shutdowns;
  EXPECT_EQ(shutdowns, 4u) << out;
}

class FailingService : public Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kPlanning; }
  void setup(ServiceContext& ctx) override { throw core::ConfigError(ctx.team().source_file, "params.planner", "no such planner"); }
};

TEST(ServiceHost, SetupErrorsPropagateAndUnknownRobotsAreRejected) {
  core::TeamConfig team = core::load_team_config(write_team("failing"));
  HostOptions options;
  options.compose = true;
  options.metrics_port = 0;
  ServiceHost host(team, options);
  EXPECT_THROW(host.add(std::make_unique<FailingService>(), "nobody"), core::ConfigError);
  host.add(std::make_unique<EchoService>(core::ServiceKind::kHlmap), "a");
  host.add(std::make_unique<FailingService>(), "a");
  EXPECT_THROW(host.start(), core::ConfigError);
  EXPECT_TRUE(host.finished());
}

}  // namespace
}  // namespace hexplore::service
