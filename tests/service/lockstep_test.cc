// Lockstep (HostOptions::lockstep, the reproducible fast mode): virtual time, delta rounds at one
// instant, the order of one step's messages, request/reply, and failures.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <thread>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "common/service/service.h"
#include "common/transport/topics.h"
#include "hexplore/v1/test_messages.pb.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::service {
namespace {

using namespace std::chrono_literals;

// A service whose setup() is a lambda, so each test wires exactly what it checks.
class ScriptedService : public Service {
 public:
  ScriptedService(core::ServiceKind kind, std::function<void(ServiceContext&)> setup)
      : kind_(kind), setup_(std::move(setup)) {}
  core::ServiceKind kind() const override { return kind_; }
  void setup(ServiceContext& ctx) override { setup_(ctx); }

 private:
  core::ServiceKind kind_;
  std::function<void(ServiceContext&)> setup_;
};

core::TeamConfig three_robots() {
  const hexplore::testing::ScratchDir scratch("lockstep");
  const std::string path = scratch.file("team.yaml");
  std::ofstream(path) << "species:\n  - builtin: SLUGCAT\nrobots:\n  - {id: a, species: SLUGCAT}\n"
                      << "  - {id: b, species: SLUGCAT}\n  - {id: c, species: SLUGCAT}\n";
  return core::load_team_config(path);
}

HostOptions lockstep_options() {
  HostOptions options;
  options.compose = true;
  options.lockstep = true;
  options.metrics_port = 0;
  options.status_period = 1000s;  // keep status messages out of the picture
  return options;
}

v1::TestPayload payload(uint64_t counter) {
  v1::TestPayload p;
  p.set_counter(counter);
  return p;
}

TEST(Lockstep, AChainOfServicesHandlesEachStepAtItsOwnVirtualTime) {
  ServiceHost host(three_robots(), lockstep_options());
  std::vector<std::pair<uint64_t, int64_t>> received;  // counter, virtual time at c; c's thread only
  std::vector<int64_t> sent_at(100, -1);  // a's thread only
  uint64_t ticks = 0;
  // a: a tick every 100 ms of virtual time; b: relays each tick; c: records, stops after 20.
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSim, [&](ServiceContext& ctx) {
    EXPECT_TRUE(ctx.lockstep());
    ctx.loop().add_timer(100ms, [&] {
      sent_at[++ticks] = ctx.now_ns();
      ctx.publisher().publish("robot/a/tick", payload(ticks));
    });
  }), "a");
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSim, [&](ServiceContext& ctx) {
    ctx.connect("a", core::ServiceKind::kSim);
    ctx.subscriber().on<v1::TestPayload>("robot/a/tick", [&ctx](const transport::Received<v1::TestPayload>& r) {
      ctx.publisher().publish("robot/b/relay", r.message);
    });
  }), "b");
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSim, [&](ServiceContext& ctx) {
    ctx.connect("b", core::ServiceKind::kSim);
    ctx.subscriber().on<v1::TestPayload>("robot/b/relay", [&](const transport::Received<v1::TestPayload>& r) {
      received.emplace_back(r.message.counter(), ctx.now_ns());
      if (received.size() == 20) ctx.loop().stop();
    });
  }), "c");
  host.start();
  host.wait();
  EXPECT_TRUE(host.finished());
  EXPECT_FALSE(host.failed());
  ASSERT_EQ(received.size(), 20u);
  for (size_t i = 0; i < received.size(); ++i) {
    EXPECT_EQ(received[i].first, i + 1);
    // Two hops, no virtual time lost: the relay arrives at the instant of its tick.
    EXPECT_EQ(received[i].second, sent_at[i + 1]);
    EXPECT_EQ(received[i].second, static_cast<int64_t>(i + 1) * 100'000'000);
  }
}

TEST(Lockstep, OneStepsMessagesAreHandledBySenderNotByArrival) {
  ServiceHost host(three_robots(), lockstep_options());
  std::vector<std::string> order;  // "<sender>:<counter>" as c handled them
  // a and b each publish three messages per tick at the same virtual instants; b sleeps less,
  // so it usually sends first. c must still see a's three, then b's three, every step.
  std::map<std::string, uint64_t> sent;  // one entry per sender, each touched by its own thread only
  sent["a"] = sent["b"] = 0;
  for (const char* robot : {"b", "a"}) {
    host.add(std::make_unique<ScriptedService>(core::ServiceKind::kHlmap, [robot, &sent](ServiceContext& ctx) {
      uint64_t& n = sent.at(robot);
      ctx.loop().add_timer(10ms, [&ctx, robot, &n] {
        if (std::string(robot) == "a") std::this_thread::sleep_for(1ms);
        for (int i = 0; i < 3; ++i) ctx.publisher().publish("team/echo", payload(++n));
      });
    }), robot);
  }
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kHlmap, [&](ServiceContext& ctx) {
    ctx.connect("a", core::ServiceKind::kHlmap);
    ctx.connect("b", core::ServiceKind::kHlmap);
    ctx.subscriber().on<v1::TestPayload>("team/echo", [&](const transport::Received<v1::TestPayload>& r) {
      order.push_back(r.header.robot_id() + ":" + std::to_string(r.message.counter()));
      if (order.size() == 60) ctx.loop().stop();
    });
  }), "c");
  host.start();
  host.wait();
  ASSERT_EQ(order.size(), 60u);
  for (size_t step = 0; step < 10; ++step) {
    for (int i = 0; i < 3; ++i) {
      const std::string n = std::to_string(step * 3 + i + 1);
      EXPECT_EQ(order[step * 6 + i], "a:" + n) << "step " << step;
      EXPECT_EQ(order[step * 6 + 3 + i], "b:" + n) << "step " << step;
    }
  }
}

TEST(Lockstep, RepliesArriveAtTheInstantOfTheRequest) {
  ServiceHost host(three_robots(), lockstep_options());
  std::vector<int64_t> asked, answered;
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kMapping, [](ServiceContext& ctx) {
    ctx.responder().serve<v1::TestPayload, v1::TestPayload>(
        [](const transport::Received<v1::TestPayload>& r) { return payload(r.message.counter() * 2); });
  }), "a");
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kStation, [&](ServiceContext& ctx) {
    ctx.loop().add_timer(250ms, [&] {
      asked.push_back(ctx.now_ns());
      ctx.requester("a", core::ServiceKind::kMapping)
          .request<v1::TestPayload, v1::TestPayload>(
              payload(asked.size()),
              [&](const transport::Received<v1::TestPayload>* reply) {
                ASSERT_NE(reply, nullptr);
                EXPECT_EQ(reply->message.counter(), 2 * asked.size());
                answered.push_back(ctx.now_ns());
                if (answered.size() == 8) ctx.loop().stop();
              },
              1s);
    });
  }), std::string(core::kStationId));
  host.start();
  host.wait();
  EXPECT_EQ(asked, answered);
  EXPECT_EQ(answered.size(), 8u);
}

TEST(Lockstep, AThrowingCallbackStopsEveryServiceAndIsReported) {
  ServiceHost host(three_robots(), lockstep_options());
  int ticks_after_failure = 0;
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSafety, [](ServiceContext& ctx) {
    ctx.loop().add_timer(2s, [] { throw std::runtime_error("scripted failure"); });
  }), "a");
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSafety, [&](ServiceContext& ctx) {
    ctx.loop().add_timer(1s, [&] {
      if (ctx.now_ns() > 2'000'000'000) ++ticks_after_failure;
    });
  }), "b");
  host.start();
  host.wait();
  EXPECT_TRUE(host.failed());
  EXPECT_TRUE(host.finished());
  EXPECT_EQ(ticks_after_failure, 0);
}

TEST(Lockstep, NeedsComposition) {
  HostOptions options = lockstep_options();
  options.compose = false;
  ServiceHost host(three_robots(), options);
  host.add(std::make_unique<ScriptedService>(core::ServiceKind::kSim, [](ServiceContext&) {}), "a");
  EXPECT_THROW(host.start(), std::logic_error);
}

}  // namespace
}  // namespace hexplore::service
