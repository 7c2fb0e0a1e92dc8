// In-process transport tests over tcp loopback (ephemeral ports) and inproc.
#include <gtest/gtest.h>

#include <filesystem>
#include <thread>
#include <zmq_addon.hpp>

#include "common/core/clock.h"
#include "common/metrics/prometheus_registry.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/status.pb.h"
#include "hexplore/v1/test_messages.pb.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::transport {
namespace {

using namespace std::chrono_literals;

const Identity kR1{"r1", "SLUGCAT", "test"};

v1::TestPayload payload(uint64_t counter, size_t bytes = 16) {
  v1::TestPayload m;
  m.set_counter(counter);
  m.set_blob(std::string(bytes, 'a'));
  return m;
}

// Publishes `probe` until the subscriber side has seen something (slow-joiner handshake).
template <typename Done>
void handshake(Publisher& pub, EventLoop& loop, const std::string& topic, Done done) {
  for (int i = 0; i < 500 && !done(); ++i) {
    pub.publish(topic, payload(0));
    loop.run_until(done, 10ms);
  }
  ASSERT_TRUE(done()) << "subscriber never connected";
}

TEST(Topics, NamesAndValidation) {
  EXPECT_EQ(topics::scan("r1"), "robot/r1/scan");
  EXPECT_EQ(topics::robot_prefix("r1"), "robot/r1/");
  EXPECT_TRUE(topics::is_valid_topic("team/map"));
  EXPECT_FALSE(topics::is_valid_topic("team/"));
  EXPECT_TRUE(topics::is_valid_prefix("team/"));
  EXPECT_FALSE(topics::is_valid_topic("robot//scan"));
  EXPECT_FALSE(topics::is_valid_topic("robot/r1/sc an"));
  EXPECT_FALSE(topics::is_valid_topic(std::string(200, 'a')));
  EXPECT_TRUE(topics::matches("team/", "team/map"));
  EXPECT_FALSE(topics::matches("team/", "robot/r1/map"));
  EXPECT_EQ(topics::topic_label(std::string("bad\ntopic")), "invalid");
  EXPECT_EQ(topics::peer_label(""), "unknown");
}

TEST(Transport, TypedPubSubFillsHeaderAndFiltersByPrefix) {
  Context ctx;
  Accounting pub_acc("r1", "test"), sub_acc("r2", "test");
  Publisher pub(ctx, kR1, "tcp://127.0.0.1:*", {}, &pub_acc);
  Subscriber sub(ctx, {}, &sub_acc);
  sub.connect(pub.endpoint());
  std::vector<uint64_t> team_sequences;
  std::vector<std::string> team_topics;
  int robot_messages = 0;
  sub.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>& m) {
    if (m.message.counter() == 0) return;  // handshake
    team_sequences.push_back(m.header.sequence());
    team_topics.emplace_back(m.topic);
    EXPECT_EQ(m.header.robot_id(), "r1");
    EXPECT_EQ(m.header.species(), "SLUGCAT");
    EXPECT_EQ(m.header.service(), "test");
    EXPECT_EQ(m.header.payload_type(), "hexplore.v1.TestPayload");
    EXPECT_EQ(m.header.sim_time_ns(), 42'000'000);  // milliseconds on the wire
    EXPECT_EQ(m.header.send_time_ns(), 0);          // the radio carries no wall time
    EXPECT_GT(m.wire_bytes, m.message.ByteSizeLong());
  });
  sub.on<v1::TestPayload>("robot/r1/", [&](const Received<v1::TestPayload>& m) {
    ++robot_messages;
    EXPECT_GT(m.header.send_time_ns(), 0);  // robot-local: wall time for the latency histogram
  });
  EventLoop loop;
  loop.add(sub);
  handshake(pub, loop, "team/hello", [&] { return sub_acc.received("team/hello").messages > 0; });
  pub.publish("team/map", payload(1), 42'000'000);
  pub.publish("team/plan", payload(2), 42'000'000);
  pub.publish("team/map", payload(3), 42'000'000);
  pub.publish("robot/r1/scan", payload(4), 42'000'000);
  pub.publish("robot/r3/scan", payload(5), 42'000'000);  // nobody subscribed: filtered by ZeroMQ
  ASSERT_TRUE(loop.run_until([&] { return team_sequences.size() == 3 && robot_messages == 1; }, 5s));
  EXPECT_EQ(team_topics, (std::vector<std::string>{"team/map", "team/plan", "team/map"}));
  EXPECT_EQ(team_sequences, (std::vector<uint64_t>{1, 1, 2}));  // per-topic sequences
  EXPECT_EQ(pub.last_sequence("team/map"), 2u);
  EXPECT_EQ(sub_acc.received("team/map").messages, 2u);
  EXPECT_EQ(sub_acc.received("team/map").bytes, pub_acc.sent("team/map").bytes);
  EXPECT_EQ(sub_acc.latency_samples("team/map"), 0u);  // no send time, no latency sample
  EXPECT_EQ(sub_acc.latency_samples("robot/r1/scan"), 1u);
  EXPECT_EQ(sub_acc.received("robot/r3/scan").messages, 0u);
}

TEST(Transport, InprocWithSharedContext) {
  Context ctx;
  Subscriber sub(ctx);
  sub.connect("inproc://pub-test");  // connect before bind works for inproc
  Publisher pub(ctx, kR1, "inproc://pub-test");
  int got = 0;
  sub.on<v1::RobotPose>("robot/r1/pose", [&](const Received<v1::RobotPose>&) { ++got; });
  EventLoop loop;
  loop.add(sub);
  for (int i = 0; i < 500 && got == 0; ++i) {
    pub.publish("robot/r1/pose", v1::RobotPose());
    loop.run_until([&] { return got > 0; }, 5ms);
  }
  EXPECT_GT(got, 0);
}

TEST(Transport, IpcEndpointCreatesItsFolder) {
  Context ctx;
  const hexplore::testing::ScratchDir scratch("hexplore_ipc");
  const std::string folder = scratch.file("nested");
  Publisher pub(ctx, kR1, "ipc://" + folder + "/r1-sim-pub");
  Subscriber sub(ctx);
  sub.connect(pub.endpoint());
  int got = 0;
  sub.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++got; });
  EventLoop loop;
  loop.add(sub);
  handshake(pub, loop, "team/hello", [&] { return got > 0; });
}

// Raw frames from a plain ZeroMQ PUB socket: every kind of bad frame is counted and dropped,
// and valid messages around them still arrive.
TEST(Transport, BadFramesAreCountedAndDroppedWhileValidTrafficContinues) {
  Context ctx;
  zmq::socket_t raw(ctx.zmq(), zmq::socket_type::pub);
  raw.bind("tcp://127.0.0.1:*");
  const std::string endpoint = raw.get(zmq::sockopt::last_endpoint);
  SocketOptions options;
  options.max_message_bytes = 1000;
  Accounting acc("r2", "test");
  Subscriber sub(ctx, options, &acc);
  sub.connect(endpoint);
  std::vector<uint64_t> valid;
  sub.on<v1::TestPayload>("robot/", [&](const Received<v1::TestPayload>& m) { valid.push_back(m.message.counter()); });
  EventLoop loop;
  loop.add(sub);

  auto header_frame = [](const std::string& type, uint32_t version = current_schema_version()) {
    v1::Header h = make_header(kR1, 1, type, 0);
    h.set_schema_version(version);
    return transport::header_frame(h, nullptr);
  };
  auto send = [&](std::vector<zmq::message_t> frames) {
    for (size_t i = 0; i < frames.size(); ++i)
      raw.send(frames[i], i + 1 < frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
  };
  auto frames = [](auto&&... parts) {
    std::vector<zmq::message_t> v;
    (v.push_back(std::move(parts)), ...);
    return v;
  };
  auto valid_message = [&](uint64_t counter) {
    send(frames(zmq::message_t(std::string("robot/r1/x")), header_frame("hexplore.v1.TestPayload"),
                to_frame(payload(counter))));
  };
  for (int i = 0; i < 500 && valid.empty(); ++i) {
    valid_message(0);
    loop.run_until([&] { return !valid.empty(); }, 10ms);
  }
  ASSERT_FALSE(valid.empty());
  valid.clear();

  const std::string topic = "robot/r1/x";
  valid_message(1);
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.TestPayload")));  // truncated: 2 frames
  valid_message(2);
  std::string runs_off("\x01\x01\x02\xff\xff garbage");
  runs_off[0] = static_cast<char>(current_schema_version() << 5 | 0x01);
  send(frames(zmq::message_t(topic), zmq::message_t(runs_off),
              to_frame(payload(9))));  // this version, named sender whose name runs off the frame
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.TestPayload", 7), to_frame(payload(9))));  // version
  {
    // A v1 (protobuf) header: what an old build sends.
    v1::Header old = make_header(kR1, 1, "hexplore.v1.TestPayload", 0);
    old.set_schema_version(1);
    send(frames(zmq::message_t(topic), to_frame(old), to_frame(payload(9))));
  }
  valid_message(3);
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.TestPayload"),
              to_frame(payload(9, 1500))));  // oversize for this subscriber
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.RobotPose"), to_frame(payload(9))));  // wrong type
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.TestPayload"),
              zmq::message_t(std::string("\x0a\xff\xff\xff"))));  // payload does not parse
  send(frames(zmq::message_t(std::string("robot/r1/bad topic")), header_frame("hexplore.v1.TestPayload"),
              to_frame(payload(9))));  // invalid topic
  send(frames(zmq::message_t(topic), header_frame("hexplore.v1.TestPayload"), to_frame(payload(9)),
              zmq::message_t(std::string("extra"))));  // 4 frames
  valid_message(4);
  ASSERT_TRUE(loop.run_until([&] { return valid.size() == 4; }, 5s));
  EXPECT_EQ(valid, (std::vector<uint64_t>{1, 2, 3, 4}));
  EXPECT_EQ(acc.dropped(DropReason::kMalformed), 5u);  // truncated, header, payload, topic, 4 frames
  EXPECT_EQ(acc.dropped(DropReason::kWrongVersion), 2u);
  EXPECT_EQ(acc.dropped(DropReason::kOversize), 1u);
  EXPECT_EQ(acc.dropped(DropReason::kWrongType), 1u);
}

TEST(Transport, AThrowingHandlerIsCountedAndTheLoopGoesOn) {
  Context ctx;
  Accounting acc("r2", "test");
  Subscriber sub(ctx, {}, &acc);
  sub.connect("inproc://throwing");
  Publisher pub(ctx, kR1, "inproc://throwing");
  std::vector<uint64_t> seen;
  sub.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>& m) {
    if (m.message.counter() == 1) throw std::out_of_range("bad index");
    seen.push_back(m.message.counter());
  });
  EventLoop loop;
  loop.add(sub);
  handshake(pub, loop, "team/hello", [&] { return !seen.empty(); });
  seen.clear();
  pub.publish("team/map", payload(1));
  pub.publish("team/map", payload(2));
  ASSERT_TRUE(loop.run_until([&] { return !seen.empty(); }, 5s));
  EXPECT_EQ(seen, (std::vector<uint64_t>{2}));
  EXPECT_EQ(acc.dropped(DropReason::kHandlerError), 1u);
}

TEST(Transport, PublisherRefusesOversizeAndInvalidTopics) {
  Context ctx;
  Accounting acc("r1", "test");
  SocketOptions options;
  options.max_message_bytes = 100;
  Publisher pub(ctx, kR1, "inproc://oversize", options, &acc);
  EXPECT_FALSE(pub.publish("team/map", payload(1, 200)));
  EXPECT_FALSE(pub.publish("team//map", payload(1)));
  EXPECT_TRUE(pub.publish("team/map", payload(1, 10)));
  EXPECT_EQ(acc.dropped(DropReason::kOversize), 1u);
  EXPECT_EQ(acc.dropped(DropReason::kMalformed), 1u);
}

TEST(Transport, FaultInjectionDropsAboutTheRequestedFraction) {
  Context ctx;
  Accounting acc("r1", "test");
  SocketOptions options;
  options.faults.drop_fraction = 0.3;
  options.faults.topic_prefixes = {"team/"};
  options.faults.seed = 7;
  Publisher pub(ctx, kR1, "inproc://faults", options, &acc);
  constexpr int kN = 10000;
  int accepted = 0;
  for (int i = 0; i < kN; ++i) accepted += pub.publish("team/map", payload(i)) ? 1 : 0;
  for (int i = 0; i < 100; ++i) EXPECT_TRUE(pub.publish("robot/r1/pose", payload(i)));  // not a chosen prefix
  const double dropped = static_cast<double>(acc.dropped(DropReason::kFaultInjected)) / kN;
  EXPECT_NEAR(dropped, 0.3, 0.03);
  EXPECT_EQ(accepted + static_cast<int>(acc.dropped(DropReason::kFaultInjected)), kN);
}

TEST(Transport, FaultInjectionDelaysMessagesThroughTheLoop) {
  Context ctx;
  SocketOptions options;
  options.faults.delay = 150ms;
  options.faults.topic_prefixes = {"team/map"};
  Subscriber sub(ctx);
  std::vector<int64_t> arrival_ns;
  sub.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { arrival_ns.push_back(core::monotonic_ns()); });
  sub.connect("inproc://delayed");
  Publisher pub(ctx, kR1, "inproc://delayed", options);
  EventLoop loop;
  loop.add(sub);
  loop.add(pub);
  handshake(pub, loop, "team/hello", [&] { return !arrival_ns.empty(); });
  arrival_ns.clear();
  const int64_t sent_ns = core::monotonic_ns();
  ASSERT_TRUE(pub.publish("team/map", payload(1)));
  EXPECT_EQ(pub.delayed_count(), 1u);
  ASSERT_TRUE(loop.run_until([&] { return !arrival_ns.empty(); }, 5s));
  EXPECT_GE(arrival_ns.front() - sent_ns, 140'000'000);
  EXPECT_EQ(pub.delayed_count(), 0u);
}

TEST(Transport, RequestReplyWithTimeoutAndUnservedType) {
  Context ctx;
  Accounting server_acc("r2", "test"), client_acc("r1", "test");
  Responder responder(ctx, Identity{"r2", "MR1000", "hlmap"}, "tcp://127.0.0.1:*", {}, &server_acc);
  responder.serve<v1::TestPayload, v1::TestPayload>([](const Received<v1::TestPayload>& r) {
    v1::TestPayload reply;
    reply.set_counter(r.message.counter() * 2);
    EXPECT_EQ(r.header.robot_id(), "r1");
    return reply;
  });
  Requester requester(ctx, kR1, responder.endpoint(), {}, &client_acc, "r2");
  EventLoop loop;
  loop.add(responder);
  loop.add(requester);

  std::optional<uint64_t> answer;
  std::string from;
  requester.request<v1::TestPayload, v1::TestPayload>(
      payload(21),
      [&](const Received<v1::TestPayload>* reply) {
        ASSERT_NE(reply, nullptr);
        answer = reply->message.counter();
        from = reply->header.robot_id();
      },
      2s);
  ASSERT_TRUE(loop.run_until([&] { return answer.has_value(); }, 5s));
  EXPECT_EQ(*answer, 42u);
  EXPECT_EQ(from, "r2");

  // A request type nobody serves gets an immediate failure, not a time-out.
  bool failed = false;
  const int64_t start = core::monotonic_ns();
  requester.request<v1::RobotPose, v1::RobotPose>(
      v1::RobotPose(), [&](const Received<v1::RobotPose>* reply) { failed = reply == nullptr; }, 3s);
  ASSERT_TRUE(loop.run_until([&] { return failed; }, 5s));
  EXPECT_LT(core::monotonic_ns() - start, 1'000'000'000);

  // No responder at all: the time-out fires.
  Requester lonely(ctx, kR1, "tcp://127.0.0.1:1", {}, &client_acc);
  loop.add(lonely);
  bool timed_out = false;
  lonely.request<v1::TestPayload, v1::TestPayload>(
      payload(1), [&](const Received<v1::TestPayload>* reply) { timed_out = reply == nullptr; }, 100ms);
  ASSERT_TRUE(loop.run_until([&] { return timed_out; }, 5s));
  EXPECT_EQ(client_acc.dropped(DropReason::kTimeout), 1u);
  EXPECT_EQ(lonely.pending(), 0u);
}

TEST(Transport, BlockingCallForTools) {
  Context ctx;
  Responder responder(ctx, Identity{"r2", "", "x"}, "inproc://call", {});
  responder.serve<v1::TestPayload, v1::TestPayload>([](const Received<v1::TestPayload>& r) { return r.message; });
  EventLoop loop;
  loop.add(responder);
  std::thread server([&] { loop.run(); });
  Requester requester(ctx, kR1, "inproc://call");
  const auto reply = requester.call<v1::TestPayload, v1::TestPayload>(payload(5), 2s);
  loop.stop();
  server.join();
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(reply->counter(), 5u);
}

TEST(EventLoop, TimersPostAndStopFromAnotherThread) {
  EventLoop loop;
  int ticks = 0;
  const auto id = loop.add_timer(5ms, [&] { ++ticks; });
  ASSERT_TRUE(loop.run_until([&] { return ticks >= 3; }, 2s));
  loop.cancel_timer(id);
  const int frozen = ticks;
  loop.run_until([] { return false; }, 30ms);
  EXPECT_EQ(ticks, frozen);

  std::atomic<bool> posted{false};
  std::thread other([&] {
    loop.post([&] { posted = true; });
    std::this_thread::sleep_for(20ms);
    loop.stop();
  });
  const int64_t start = core::monotonic_ns();
  loop.run();  // returns once the other thread calls stop()
  other.join();
  EXPECT_TRUE(posted);
  EXPECT_LT(core::monotonic_ns() - start, 1'000'000'000);
}

TEST(Accounting, FeedsPrometheusFamilies) {
  metrics::PrometheusRegistry registry;
  const auto families = metrics::TransportFamilies::create(registry);
  Accounting acc("r1", "hlmap", &families);
  acc.record_sent("team/map", kBroadcastPeer, 100);
  acc.record_received("team/map", "r2", 80, 2'000'000);
  acc.record_dropped("team/map", DropReason::kWrongVersion);
  const std::string text = registry.serialize();
  EXPECT_NE(text.find("hexplore_transport_sent_bytes_total{peer=\"broadcast\",robot=\"r1\",service=\"hlmap\",topic=\"team/map\"} 100"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("hexplore_transport_received_messages_total{peer=\"r2\",robot=\"r1\",service=\"hlmap\",topic=\"team/map\"} 1"),
            std::string::npos);
  EXPECT_NE(text.find("hexplore_transport_dropped_total{reason=\"wrong_version\",robot=\"r1\",service=\"hlmap\",topic=\"team/map\"} 1"),
            std::string::npos);
  EXPECT_NE(text.find("hexplore_transport_latency_seconds_count{robot=\"r1\",service=\"hlmap\",topic=\"team/map\"} 1"),
            std::string::npos);
}

}  // namespace
}  // namespace hexplore::transport
