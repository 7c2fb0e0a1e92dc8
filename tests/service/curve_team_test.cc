// Authenticated team links end to end: hexplore_keys makes a team's keys, two service
// processes (robots a and b) talk over CURVE and keep working while a rogue with a
// valid-looking but unknown key and one with no key are refused (nothing delivered, no request
// answered) and counted on the service's /metrics.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/service/team_keys.h"
#include "common/transport/event_loop.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/status.pb.h"
#include "hexplore/v1/test_messages.pb.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_ports.h"
#include "tests/transport/child_process.h"

namespace hexplore::service {
namespace {

using namespace std::chrono_literals;
using testing::ChildProcess;

std::string write_team(const hexplore::testing::ScratchDir& dir) {
  const int base_port = hexplore::testing::random_base_port();
  const std::string path = dir.file("team.yaml");
  std::ofstream(path) << "species:\n  - builtin: SLUGCAT\nrobots:\n  - {id: a, species: SLUGCAT}\n"
                      << "  - {id: b, species: SLUGCAT}\ntransport:\n  scheme: tcp\n  base_port: " << base_port
                      << "\n  curve_keys_dir: keys\n";
  return path;
}

double metric(int port, const std::string& series) {
  const std::string file = ::testing::TempDir() + "/curve_metrics_" + std::to_string(getpid());
  if (std::system(("curl -s -f -m 5 -o '" + file + "' http://127.0.0.1:" + std::to_string(port) + "/metrics").c_str()) != 0)
    return -1.0;
  std::stringstream body;
  body << std::ifstream(file).rdbuf();
  const std::string text = "\n" + body.str();  // a sample starts a line (not "# HELP <name> ...")
  const size_t at = text.find("\n" + series + " ");
  return at == std::string::npos ? 0.0 : std::stod(text.substr(at + series.size() + 2));
}

TEST(CurveTeam, KeysToolThenTheTeamWorksAndRoguesAreRefusedAndCounted) {
  const hexplore::testing::ScratchDir dir("curve_team");
  const std::string path = write_team(dir);
  {
    ChildProcess keys({HEXPLORE_KEYS_PATH, "--config", path});
    ASSERT_EQ(keys.wait_exit(30s), 0) << keys.output();
    EXPECT_NE(keys.output().find("3 new key pair(s), 3 members"), std::string::npos) << keys.output();
    ChildProcess again({HEXPLORE_KEYS_PATH, "--config", path});  // keeps a running team's keys
    ASSERT_EQ(again.wait_exit(30s), 0) << again.output();
    EXPECT_NE(again.output().find("0 new key pair(s)"), std::string::npos) << again.output();
  }
  const core::TeamConfig team = core::load_team_config(path);
  ASSERT_EQ(team.transport.curve_keys_dir, dir.file("keys"));  // relative to the team file

  ChildProcess a({ECHO_SERVICE_PATH, "--config", path, "--robot", "a", "--metrics-port", "-1", "--status-period-ms", "100"});
  ChildProcess b({ECHO_SERVICE_PATH, "--config", path, "--robot", "b", "--status-period-ms", "100"});
  const auto metrics_line = a.wait_for_line("serving /metrics on port ", 10s);
  ASSERT_TRUE(metrics_line) << a.output();
  const int metrics_port = std::stoi(metrics_line->substr(metrics_line->rfind(' ') + 1));
  const std::string pub = core::connect_endpoint(team, "a", core::ServiceKind::kMapping, core::SocketRole::kPublish);
  const std::string req = core::connect_endpoint(team, "a", core::ServiceKind::kMapping, core::SocketRole::kRequest);

  // The operator, with the station's key: sees a's status, in which a counts b's messages.
  const auto ring = team_keyring(team);
  transport::SocketOptions station;
  station.curve = member_credentials(team, ring, std::string(core::kStationId));
  transport::Context context;
  transport::Subscriber watcher(context, station);
  watcher.connect(pub, "a");
  double teammate_messages = 0.0;
  watcher.on<v1::ServiceStatus>("robot/a/status", [&](const transport::Received<v1::ServiceStatus>& m) {
    for (const auto& v : m.message.values())
      if (v.name() == "teammate_messages") teammate_messages = v.value();
  });

  // The rogues: a well-formed pair nobody listed (knowing a's public key), and no keys at all.
  transport::SocketOptions rogue;
  rogue.curve = std::make_shared<transport::CurveCredentials>(
      transport::CurveCredentials{"b", transport::generate_curve_key_pair(), ring});
  transport::Subscriber rogue_sub(context, rogue), plain_sub(context);
  rogue_sub.connect(pub, "a");
  plain_sub.connect(pub);
  int rogue_got = 0;
  rogue_sub.on<v1::ServiceStatus>("robot/", [&](const transport::Received<v1::ServiceStatus>&) { ++rogue_got; });
  plain_sub.on<v1::ServiceStatus>("robot/", [&](const transport::Received<v1::ServiceStatus>&) { ++rogue_got; });
  transport::Requester rogue_req(context, {"b", "SLUGCAT", "rogue"}, req, rogue, nullptr, "a");
  bool rogue_answered = false, rogue_timed_out = false;
  v1::TestPayload burst;
  burst.set_counter(5);
  rogue_req.request<v1::TestPayload, v1::TestPayload>(burst, [&](const transport::Received<v1::TestPayload>* r) {
    (r ? rogue_answered : rogue_timed_out) = true;
  }, 3s);

  transport::EventLoop loop;
  loop.add(watcher);
  loop.add(rogue_sub);
  loop.add(plain_sub);
  loop.add(rogue_req);
  // The team works: a has heard b over CURVE, and keeps hearing it.
  ASSERT_TRUE(loop.run_until([&] { return teammate_messages >= 20.0; }, 20s)) << a.output() << b.output();
  ASSERT_TRUE(loop.run_until([&] { return rogue_timed_out || rogue_answered; }, 10s));
  EXPECT_FALSE(rogue_answered) << "a rogue's request was served";
  EXPECT_TRUE(rogue_timed_out);
  EXPECT_EQ(rogue_got, 0) << "a rogue received a's messages";
  const double before = teammate_messages;
  loop.run_until([&] { return teammate_messages >= before + 20.0; }, 10s);
  EXPECT_GE(teammate_messages, before + 20.0) << "the team stopped working beside the rogues";

  const double unknown = metric(metrics_port, "hexplore_transport_rejected_peers_total{reason=\"unknown_key\"}");
  const double handshake = metric(metrics_port, "hexplore_transport_rejected_peers_total{reason=\"handshake\"}");
  EXPECT_GE(unknown, 1.0) << "unknown keys not counted";
  EXPECT_GE(handshake, 1.0) << "peers without keys not counted";
  EXPECT_EQ(a.output().find("refused a peer with an unknown CURVE key"),
            a.output().rfind("refused a peer with an unknown CURVE key"))
      << "logged more than once per key:\n" << a.output();
}

// The station relays mission commands only for the holder of the station's key: a robot's key
// (a teammate, or whoever stole it) is refused and counted.
TEST(CurveTeam, OnlyTheStationsKeyCommandsTheTeam) {
  const hexplore::testing::ScratchDir dir("curve_station");
  const std::string path = write_team(dir);
  ChildProcess keys({HEXPLORE_KEYS_PATH, "--config", path});
  ASSERT_EQ(keys.wait_exit(30s), 0) << keys.output();
  const core::TeamConfig team = core::load_team_config(path);
  ChildProcess station({STATION_PATH, "--config", path, "--results", dir.file("results"), "--report", "false",
                        "--autostart", "false", "--metrics-port", "-1"});
  const auto metrics_line = station.wait_for_line("serving /metrics on port ", 20s);
  ASSERT_TRUE(metrics_line) << station.output();
  const int metrics_port = std::stoi(metrics_line->substr(metrics_line->rfind(' ') + 1));
  const std::string endpoint =
      core::connect_endpoint(team, std::string(core::kStationId), core::ServiceKind::kStation, core::SocketRole::kRequest);
  const auto ring = team_keyring(team);
  v1::MissionCommand stop;
  stop.mutable_stop();
  auto ask = [&](const std::string& member) -> std::string {
    transport::SocketOptions options;
    options.curve = member_credentials(team, ring, member);
    transport::Context context;
    transport::Requester requester(context, {member, "", "test"}, endpoint, options, nullptr,
                                   std::string(core::kStationId));
    for (int attempt = 0; attempt < 10; ++attempt)  // the station may still be starting
      if (const auto reply = requester.call<v1::MissionCommand, v1::ServiceStatus>(stop, 2000ms)) return reply->detail();
    return "no reply";
  };
  EXPECT_EQ(ask("a").rfind("refused", 0), 0u) << "a robot's key commanded the team";
  EXPECT_EQ(ask(std::string(core::kStationId)).rfind("relayed", 0), 0u);
  EXPECT_GE(metric(metrics_port, "hexplore_station_refused_commands_total"), 1.0);
}

}  // namespace
}  // namespace hexplore::service
