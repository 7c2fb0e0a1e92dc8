// The radio link model: a robot's serial channel (bandwidth, queue age), latency, loss drawn
// per (message, receiver), range from the sims' positions, the lockstep commit order; and the
// model applied by real sockets: what arrives, what is dropped, counted by reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/transport/event_loop.h"
#include "common/transport/link_model.h"
#include "common/transport/publisher.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/test_messages.pb.h"

namespace hexplore::transport {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<const Roster> roster() {
  return std::make_shared<const Roster>(std::vector<Roster::Member>{{"r1", "SLUGCAT"}, {"r2", "MR1000"}, {"r3", "MR1000"}});
}

core::RadioConfig radio(double bandwidth, double latency, double loss, double range) {
  core::RadioConfig c;
  c.bandwidth_bytes_per_s = bandwidth;
  c.latency_s = latency;
  c.loss = loss;
  c.range_m = range;
  return c;
}

// Submits `bytes` from `slot` at `t_ns`; records when it is due or that it expired.
struct Outcome {
  std::vector<int64_t> due;
  int expired = 0;
};
void submit(RadioMedium& m, uint32_t slot, int64_t t_ns, size_t bytes, Outcome& out, uint32_t service = 0,
            uint64_t order = 0) {
  RadioMedium::Submission s;
  s.sender_slot = slot;
  s.service = service;
  s.order = order;
  s.submit_ns = t_ns;
  s.bytes = bytes;
  s.schedule = [&out](int64_t due) { out.due.push_back(due); };
  s.expire = [&out] { ++out.expired; };
  m.submit(std::move(s));
}

TEST(LinkModel, ARobotsChannelIsSerialAndOldMessagesExpire) {
  core::RadioConfig c = radio(1000.0, 0.2, 0.0, 0.0);
  c.max_queue_age_s = 0.35;
  RadioMedium m(c, roster(), 1, false);
  Outcome a, b;
  for (int i = 0; i < 6; ++i) submit(m, 1, 0, 100, a);  // 0.1 s of airtime each
  submit(m, 2, 0, 100, b);                               // another robot's channel is its own
  // Starts at 0, 0.1, 0.2, 0.3 (within the 0.35 s queue age); the 5th and 6th would wait 0.4+.
  ASSERT_EQ(a.due.size(), 4u);
  for (size_t i = 0; i < a.due.size(); ++i) EXPECT_EQ(a.due[i], int64_t(100'000'000 * (i + 1)) + 200'000'000);
  EXPECT_EQ(a.expired, 2);
  ASSERT_EQ(b.due.size(), 1u);
  EXPECT_EQ(b.due[0], 300'000'000);
  // Once the queue has drained, a message goes at once again.
  submit(m, 1, 2'000'000'000, 100, a);
  EXPECT_EQ(a.due.back(), 2'300'000'000);
}

TEST(LinkModel, WithoutACapOnlyTheLatencyApplies) {
  RadioMedium m(radio(0.0, 0.05, 0.0, 0.0), roster(), 1, false);
  Outcome a;
  for (int i = 0; i < 100; ++i) submit(m, 1, 7, 100'000, a);
  ASSERT_EQ(a.due.size(), 100u);
  EXPECT_TRUE(std::all_of(a.due.begin(), a.due.end(), [](int64_t d) { return d == 50'000'007; }));
}

TEST(LinkModel, LockstepSchedulesAStepInAFixedOrderAtCommit) {
  // What the services of one robot submit in a step, in whatever order their threads ran,
  // leaves the channel in (service, submission) order.
  auto run = [](std::vector<std::pair<uint32_t, uint64_t>> order) {
    RadioMedium m(radio(1000.0, 0.0, 0.0, 0.0), roster(), 1, true);
    std::vector<std::pair<uint32_t, int64_t>> due;  // (service, due)
    for (auto [service, n] : order) {
      RadioMedium::Submission s;
      s.sender_slot = 1;
      s.service = service;
      s.order = n;
      s.submit_ns = 0;
      s.bytes = 100;
      s.schedule = [&due, service = service](int64_t d) { due.emplace_back(service, d); };
      s.expire = [] {};
      m.submit(std::move(s));
    }
    EXPECT_TRUE(due.empty());  // nothing before the step ends
    m.commit();
    std::sort(due.begin(), due.end(), [](auto& a, auto& b) { return a.second < b.second; });
    return due;
  };
  const auto first = run({{3, 1}, {0, 1}, {3, 2}, {2, 1}});
  const auto second = run({{2, 1}, {3, 2}, {0, 1}, {3, 1}});
  EXPECT_EQ(first, second);
  EXPECT_EQ(first.front().first, 0u);
}

TEST(LinkModel, LossIsPerReceiverAndTheSameForEveryServiceOfIt) {
  RadioMedium m(radio(0.0, 0.0, 0.1, 0.0), roster(), 42, false);
  int lost2 = 0, lost3 = 0, both = 0;
  const int n = 20000;
  for (int seq = 1; seq <= n; ++seq) {
    const bool a = m.receive(1, 2, "team/map", seq, 0) == RadioVerdict::kLost;
    const bool b = m.receive(1, 3, "team/map", seq, 0) == RadioVerdict::kLost;
    EXPECT_EQ(a, m.receive(1, 2, "team/map", seq, 5) == RadioVerdict::kLost);  // asked again: same answer
    lost2 += a;
    lost3 += b;
    both += a && b;
  }
  EXPECT_NEAR(lost2 / double(n), 0.1, 0.01);
  EXPECT_NEAR(lost3 / double(n), 0.1, 0.01);
  EXPECT_NEAR(both / double(n), 0.01, 0.004);  // independent receivers
}

TEST(LinkModel, BeyondTheRangeThereIsNoLink) {
  RadioMedium m(radio(0.0, 0.0, 0.0, 10.0), roster(), 1, true);
  m.enable_range(true);
  // Until both sims have reported, nobody can say the robots are apart.
  EXPECT_EQ(m.receive(1, 2, "team/pose", 1, 100), RadioVerdict::kDelivered);
  m.positions().update(1, 0, {0, 0, 0});
  m.positions().update(2, 0, {9, 0, 0});
  EXPECT_EQ(m.receive(1, 2, "team/pose", 1, 100), RadioVerdict::kDelivered);
  m.positions().update(2, 100, {11, 0, 0});
  // A position stamped at the receiver's own time may still be written in lockstep: not used.
  EXPECT_EQ(m.receive(1, 2, "team/pose", 2, 100), RadioVerdict::kDelivered);
  EXPECT_EQ(m.receive(1, 2, "team/pose", 2, 101), RadioVerdict::kOutOfRange);
  EXPECT_EQ(m.receive(2, 1, "team/pose", 2, 101), RadioVerdict::kOutOfRange);  // both ways
  m.enable_range(false);  // a process that does not simulate the whole team cannot tell
  EXPECT_EQ(m.receive(1, 2, "team/pose", 3, 101), RadioVerdict::kDelivered);
}

TEST(LinkModel, APartitionCutsARobotOffBothWaysForItsWindowOnly) {
  core::RadioConfig c;
  c.outages.push_back({"r2", 10.0, 20.0});
  RadioMedium m(c, roster(), 1, true);
  EXPECT_EQ(m.receive(1, 2, "team/map", 1, 15'000'000'000), RadioVerdict::kDelivered);  // not modelled yet
  m.enable_outages(true);
  EXPECT_EQ(m.receive(1, 2, "team/map", 1, 9'999'999'999), RadioVerdict::kDelivered);
  EXPECT_EQ(m.receive(1, 2, "team/map", 2, 10'000'000'000), RadioVerdict::kOutOfRange);
  EXPECT_EQ(m.receive(2, 3, "team/map", 2, 15'000'000'000), RadioVerdict::kOutOfRange);  // nor heard
  EXPECT_EQ(m.receive(1, 3, "team/map", 2, 15'000'000'000), RadioVerdict::kDelivered);   // the others talk on
  EXPECT_EQ(m.receive(1, 2, "team/map", 3, 20'000'000'000), RadioVerdict::kDelivered);   // healed
  core::RadioConfig stranger;
  stranger.outages.push_back({"r9", 1.0, 2.0});
  EXPECT_THROW(RadioMedium(stranger, roster(), 1, true), std::invalid_argument);
}

TEST(LinkModel, SocketsApplyItToTeamTopicsBetweenRobotsOnly) {
  Context ctx;
  auto medium = std::make_shared<RadioMedium>(radio(0.0, 0.05, 0.5, 0.0), roster(), 3, false);
  SocketOptions options;
  options.roster = roster();
  options.radio = medium;
  Accounting pub_acc("r1", "test"), r2_acc("r2", "test"), station_acc("station", "test");
  Publisher pub(ctx, Identity{"r1", "SLUGCAT", "hlmap"}, "inproc://radio", options, &pub_acc);
  SocketOptions r2_options = options;
  r2_options.receiver_robot = "r2";
  Subscriber r2(ctx, r2_options, &r2_acc);
  SocketOptions station_options = options;
  station_options.receiver_robot = "station";
  Subscriber station(ctx, station_options, &station_acc);
  int r2_team = 0, r2_local = 0, station_team = 0;
  r2.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>& m) { r2_team += m.message.counter() > 0; });
  r2.on<v1::TestPayload>("robot/", [&](const Received<v1::TestPayload>&) { ++r2_local; });
  station.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>& m) { station_team += m.message.counter() > 0; });
  r2.connect("inproc://radio");
  station.connect("inproc://radio");
  EventLoop loop;
  loop.add(r2);
  loop.add(station);
  loop.add(pub);
  v1::TestPayload probe;
  for (int i = 0; i < 200 && station_acc.received("team/hello").messages == 0; ++i) {
    pub.publish("team/hello", probe);
    loop.run_until([&] { return station_acc.received("team/hello").messages > 0; }, 10ms);
  }
  const auto start = std::chrono::steady_clock::now();
  const int n = 400;
  for (int i = 1; i <= n; ++i) {
    v1::TestPayload m;
    m.set_counter(static_cast<uint64_t>(i));
    pub.publish("team/map", m);
    pub.publish("robot/r1/x", m);
  }
  EXPECT_GT(pub.delayed_count(), 0u);  // on the radio: waiting out the latency
  ASSERT_TRUE(loop.run_until([&] { return station_team == n && r2_local == n; }, 5s));
  EXPECT_GE(std::chrono::steady_clock::now() - start, 50ms);
  loop.run_until([] { return false; }, 50ms);
  // The station, the experiment's recorder, hears everything; r2 loses about half.
  EXPECT_EQ(station_team, n);
  EXPECT_NEAR(r2_team, n / 2, n / 8);
  EXPECT_EQ(r2_acc.dropped(DropReason::kRadioLost) >= static_cast<uint64_t>(n - r2_team), true);
  EXPECT_EQ(r2_local, n);  // robot-local topics never cross the radio
}

}  // namespace
}  // namespace hexplore::transport
