// Cross-process transport tests: this test process (robot r1) and an echo_peer process
// (robot r2) exchange typed messages over tcp loopback on ephemeral ports. The peer's
// counters are read from its /metrics endpoint over HTTP.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "common/metrics/prometheus_registry.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/test_messages.pb.h"
#include "tests/transport/child_process.h"

namespace hexplore::transport {
namespace {

using namespace std::chrono_literals;
using testing::ChildProcess;

// "name{labels} value" lines of a Prometheus text exposition, keyed by "name{labels}".
std::map<std::string, double> parse_exposition(const std::string& text, bool& ok) {
  std::map<std::string, double> samples;
  static const std::regex kSample(R"(^([a-zA-Z_:][a-zA-Z0-9_:]*(\{[^}]*\})?) ([-+0-9.eE]+|NaN|Nan|\+Inf|-Inf)$)");
  std::istringstream in(text);
  ok = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch m;
    if (!std::regex_match(line, m, kSample)) {
      ADD_FAILURE() << "unparsable exposition line: " << line;
      ok = false;
      continue;
    }
    samples[m[1]] = std::stod(m[3]);
  }
  return samples;
}

std::string http_get_metrics(int port) {
  const std::string file = ::testing::TempDir() + "/metrics_" + std::to_string(getpid()) + ".txt";
  const std::string command =
      "curl -s -f -m 5 -o '" + file + "' http://127.0.0.1:" + std::to_string(port) + "/metrics";
  if (std::system(command.c_str()) != 0) return "";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(file.c_str());
  return text.str();
}

std::string value_after(const std::string& line, const std::string& key) {
  return line.substr(line.find(key) + key.size());
}

// Starts echo_peer and reads the endpoints it prints.
struct Peer {
  explicit Peer(std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {ECHO_PEER_PATH, "--robot", "r2"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    process = std::make_unique<ChildProcess>(argv);
    const auto pub_line = process->wait_for_line("pub ", 10s);
    const auto req_line = process->wait_for_line("req ", 10s);
    const auto metrics_line = process->wait_for_line("metrics ", 10s);
    if (!pub_line || !req_line || !metrics_line || !process->wait_for_line("ready", 10s)) {
      ADD_FAILURE() << "echo_peer did not start: " << process->output(100ms);
      return;
    }
    pub = value_after(*pub_line, "pub ");
    req = value_after(*req_line, "req ");
    metrics_port = std::stoi(value_after(*metrics_line, "metrics "));
  }
  std::unique_ptr<ChildProcess> process;
  std::string pub, req;
  int metrics_port = 0;
};

class TwoProcess : public ::testing::Test {
 protected:
  TwoProcess() : families(metrics::TransportFamilies::create(registry)), accounting("r1", "test", &families) {}
  metrics::PrometheusRegistry registry;
  metrics::TransportFamilies families;
  Accounting accounting;
  Context context;
  EventLoop loop;
};

TEST_F(TwoProcess, ExchangeTypedMessagesAndCountersMatch) {
  Publisher publisher(context, Identity{"r1", "SLUGCAT", "test"}, "tcp://127.0.0.1:*", {}, &accounting);
  Peer peer({"--connect", publisher.endpoint()});
  ASSERT_GT(peer.metrics_port, 0);
  Subscriber subscriber(context, {}, &accounting);
  subscriber.connect(peer.pub);
  int hello_echoes = 0;
  std::vector<uint64_t> pongs;
  std::vector<uint64_t> burst;
  subscriber.on<v1::TestPayload>("robot/r2/", [&](const Received<v1::TestPayload>& m) {
    EXPECT_EQ(m.header.robot_id(), "r2");
    if (m.topic == "robot/r2/hello_echo") ++hello_echoes;
    if (m.topic == "robot/r2/ping_echo") pongs.push_back(m.message.counter());
    if (m.topic == "robot/r2/burst") burst.push_back(m.message.counter());
  });
  loop.add(subscriber);
  v1::TestPayload message;
  message.set_blob(std::string(200, 'p'));
  // Both directions are connected once a hello has made the round trip.
  for (int i = 0; i < 500 && hello_echoes == 0; ++i) {
    publisher.publish("robot/r1/hello", message);
    loop.run_until([&] { return hello_echoes > 0; }, 10ms);
  }
  ASSERT_GT(hello_echoes, 0) << peer.process->output(100ms);

  constexpr int kPings = 300;
  for (int i = 1; i <= kPings; ++i) {
    message.set_counter(i);
    ASSERT_TRUE(publisher.publish("robot/r1/ping", message));
  }
  ASSERT_TRUE(loop.run_until([&] { return pongs.size() == kPings; }, 10s)) << pongs.size();
  for (int i = 0; i < kPings; ++i) ASSERT_EQ(pongs[i], static_cast<uint64_t>(i + 1));

  // A request makes the peer publish a burst.
  Requester requester(context, Identity{"r1", "SLUGCAT", "test"}, peer.req, {}, &accounting, "r2");
  loop.add(requester);
  constexpr int kBurst = 2000;
  v1::TestPayload request;
  request.set_counter(kBurst);
  request.set_blob(std::string(200, 'b'));
  bool replied = false;
  requester.request<v1::TestPayload, v1::TestPayload>(
      request, [&](const Received<v1::TestPayload>* r) { replied = r != nullptr && r->message.counter() == kBurst; },
      5s);
  ASSERT_TRUE(loop.run_until([&] { return replied && burst.size() == kBurst; }, 10s)) << burst.size();

  // Our own counters.
  EXPECT_EQ(accounting.sent("robot/r1/ping").messages, static_cast<uint64_t>(kPings));
  EXPECT_EQ(accounting.received("robot/r2/ping_echo").messages, static_cast<uint64_t>(kPings));
  EXPECT_EQ(accounting.received("robot/r2/burst").messages, static_cast<uint64_t>(kBurst));
  EXPECT_EQ(accounting.latency_samples("robot/r2/burst"), static_cast<uint64_t>(kBurst));
  const std::string own = registry.serialize();
  EXPECT_NE(own.find("hexplore_transport_latency_seconds_count{robot=\"r1\",service=\"test\",topic=\"robot/r2/burst\"} " +
                     std::to_string(kBurst)),
            std::string::npos)
      << own;

  // The peer's counters, scraped over HTTP, match what went over the wire.
  const std::string text = http_get_metrics(peer.metrics_port);
  ASSERT_FALSE(text.empty()) << "scrape of /metrics failed";
  bool parsed = false;
  const auto samples = parse_exposition(text, parsed);
  EXPECT_TRUE(parsed);
  for (const char* family : {"hexplore_transport_sent_messages_total", "hexplore_transport_sent_bytes_total",
                             "hexplore_transport_received_messages_total", "hexplore_transport_received_bytes_total",
                             "hexplore_transport_latency_seconds"})
    EXPECT_NE(text.find(std::string("# TYPE ") + family), std::string::npos) << family;
  auto sample = [&](const std::string& key) {
    auto it = samples.find(key);
    return it == samples.end() ? -1.0 : it->second;
  };
  EXPECT_EQ(sample("hexplore_transport_received_messages_total{peer=\"r1\",robot=\"r2\",service=\"echo\",topic=\"robot/r1/ping\"}"),
            kPings);
  EXPECT_EQ(sample("hexplore_transport_received_bytes_total{peer=\"r1\",robot=\"r2\",service=\"echo\",topic=\"robot/r1/ping\"}"),
            static_cast<double>(accounting.sent("robot/r1/ping").bytes));
  EXPECT_EQ(sample("hexplore_transport_sent_messages_total{peer=\"broadcast\",robot=\"r2\",service=\"echo\",topic=\"robot/r2/ping_echo\"}"),
            kPings);
  EXPECT_EQ(sample("hexplore_transport_sent_bytes_total{peer=\"broadcast\",robot=\"r2\",service=\"echo\",topic=\"robot/r2/burst\"}"),
            static_cast<double>(accounting.received("robot/r2/burst").bytes));
  EXPECT_EQ(sample("hexplore_transport_latency_seconds_count{robot=\"r2\",service=\"echo\",topic=\"robot/r1/ping\"}"),
            kPings);

  const auto stop_start = std::chrono::steady_clock::now();
  peer.process->signal(SIGTERM);
  EXPECT_EQ(peer.process->wait_exit(10s), 0);
  // Bound: the civetweb exposer inside prometheus-cpp needs up to 2 s to stop (its poll quantum),
  // and the transport flush overlaps with it.
  EXPECT_LT(std::chrono::steady_clock::now() - stop_start, 4s);
}

// SIGTERM right after a burst was queued: the peer stops cleanly and no queued message is lost.
TEST_F(TwoProcess, SigtermFlushesQueuedMessages) {
  Peer peer;
  Subscriber subscriber(context, {}, &accounting);
  subscriber.connect(peer.pub);
  uint64_t received = 0, last = 0;
  subscriber.on<v1::TestPayload>("robot/r2/burst", [&](const Received<v1::TestPayload>& m) {
    ++received;
    last = m.message.counter();
  });
  loop.add(subscriber);
  Requester requester(context, Identity{"r1", "", "test"}, peer.req, {}, &accounting, "r2");
  loop.add(requester);
  // Handshake: small bursts until one arrives, so the subscription is in place.
  for (int i = 0; i < 100 && received == 0; ++i) {
    v1::TestPayload probe;
    probe.set_counter(1);
    requester.request<v1::TestPayload, v1::TestPayload>(probe, [](const Received<v1::TestPayload>*) {}, 1s);
    loop.run_until([&] { return received > 0; }, 50ms);
  }
  ASSERT_GT(received, 0u);
  loop.run_until([] { return false; }, 50ms);  // let stray probes land
  received = 0;

  constexpr uint64_t kBurst = 5000;
  v1::TestPayload request;
  request.set_counter(kBurst);
  request.set_blob(std::string(4000, 'z'));  // 20 MB in flight when the signal lands
  requester.request<v1::TestPayload, v1::TestPayload>(request, [](const Received<v1::TestPayload>*) {}, 5s);
  bool sent = false;  // sticky: a line is consumed once it is found
  ASSERT_TRUE(loop.run_until([&] { return sent = sent || peer.process->wait_for_line("burst-sent 5000", 0ms); }, 10s));
  peer.process->signal(SIGTERM);
  EXPECT_TRUE(loop.run_until([&] { return received == kBurst; }, 15s)) << received;
  EXPECT_EQ(last, kBurst);
  EXPECT_EQ(peer.process->wait_exit(10s), 0);
  EXPECT_NE(peer.process->output().find("stopping"), std::string::npos);
}

// Fault injection in a real peer: about the requested fraction of a burst is missing.
TEST_F(TwoProcess, FaultInjectionDropsAFractionOfABurst) {
  Peer peer({"--drop", "0.25", "--fault-prefix", "robot/r2/burst"});
  Subscriber subscriber(context, {}, &accounting);
  subscriber.connect(peer.pub);
  uint64_t received = 0;
  subscriber.on<v1::TestPayload>("robot/r2/burst", [&](const Received<v1::TestPayload>&) { ++received; });
  loop.add(subscriber);
  Requester requester(context, Identity{"r1", "", "test"}, peer.req, {}, &accounting, "r2");
  loop.add(requester);
  for (int i = 0; i < 100 && received == 0; ++i) {
    v1::TestPayload probe;
    probe.set_counter(4);
    requester.request<v1::TestPayload, v1::TestPayload>(probe, [](const Received<v1::TestPayload>*) {}, 1s);
    loop.run_until([&] { return received > 0; }, 50ms);
  }
  ASSERT_GT(received, 0u);
  loop.run_until([] { return false; }, 50ms);
  received = 0;
  constexpr uint64_t kBurst = 4000;
  v1::TestPayload request;
  request.set_counter(kBurst);
  requester.request<v1::TestPayload, v1::TestPayload>(request, [](const Received<v1::TestPayload>*) {}, 5s);
  bool sent = false;  // sticky: a line is consumed once it is found
  ASSERT_TRUE(loop.run_until([&] { return sent = sent || peer.process->wait_for_line("burst-sent 4000", 0ms); }, 10s));
  loop.run_until([&] { return received >= kBurst; }, 500ms);  // nothing more will come once the queue drained
  const double fraction_dropped = 1.0 - static_cast<double>(received) / kBurst;
  EXPECT_NEAR(fraction_dropped, 0.25, 0.04) << received;
  const std::string text = http_get_metrics(peer.metrics_port);
  EXPECT_NE(text.find("hexplore_transport_dropped_total{reason=\"fault_injected\",robot=\"r2\",service=\"echo\",topic=\"robot/r2/burst\"}"),
            std::string::npos);
}

}  // namespace
}  // namespace hexplore::transport
