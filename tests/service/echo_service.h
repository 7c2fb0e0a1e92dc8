#pragma once
// A minimal Service for the service-base tests: it publishes a TestPayload on team/echo every
// `period`, counts the team/echo messages of its teammates, and on a TestPayload request
// {counter = N, blob of B bytes} publishes N messages of B bytes on robot/<id>/burst.

#include <atomic>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "common/service/service.h"
#include "common/transport/topics.h"
#include "hexplore/v1/test_messages.pb.h"

namespace hexplore::testing {

class EchoService : public service::Service {
 public:
  explicit EchoService(core::ServiceKind kind, std::chrono::milliseconds period = std::chrono::milliseconds(20))
      : kind_(kind), period_(period) {}

  core::ServiceKind kind() const override { return kind_; }

  void setup(service::ServiceContext& ctx) override {
    for (const auto& robot : ctx.team().robots)
      if (robot.id != ctx.robot_id()) ctx.connect(robot.id, kind_);
    ctx.subscriber().on<v1::TestPayload>("team/echo", [this, &ctx](const transport::Received<v1::TestPayload>& m) {
      if (m.header.robot_id() != ctx.robot_id()) teammate_messages.fetch_add(1);
    });
    ctx.loop().add_timer(period_, [this, &ctx] {
      v1::TestPayload message;
      message.set_counter(++sent_);
      ctx.publisher().publish("team/echo", message);
    });
    ctx.responder().serve<v1::TestPayload, v1::TestPayload>([&ctx](const transport::Received<v1::TestPayload>& r) {
      const uint64_t count = r.message.counter();
      const size_t bytes = r.message.blob().size();
      ctx.loop().post([&ctx, count, bytes] {
        v1::TestPayload message;
        message.set_blob(std::string(bytes, 'x'));
        const std::string topic = transport::topics::robot_topic(ctx.robot_id(), "burst");
        for (uint64_t i = 1; i <= count; ++i) {
          message.set_counter(i);
          ctx.publisher().publish(topic, message);
        }
        std::printf("burst-sent %llu\n", static_cast<unsigned long long>(count));
        std::fflush(stdout);
      });
      v1::TestPayload reply;
      reply.set_counter(count);
      return reply;
    });
    // --throw-after-ms N: a callback throws after N ms (tests the failure exit code).
    if (auto it = ctx.arguments().find("throw-after-ms"); it != ctx.arguments().end())
      ctx.loop().add_timer(std::chrono::milliseconds(std::stoi(it->second)),
                           [] { throw std::runtime_error("echo service asked to fail"); });
    setup_done.store(true);
  }

  void on_shutdown(service::ServiceContext&) override {
    std::printf("shutdown %s\n", name().c_str());
    std::fflush(stdout);
  }

  void fill_status(v1::ServiceStatus& status) override {
    auto* value = status.add_values();
    value->set_name("teammate_messages");
    value->set_value(static_cast<double>(teammate_messages.load()));
  }

  std::atomic<bool> setup_done{false};
  std::atomic<uint64_t> teammate_messages{0};

 private:
  core::ServiceKind kind_;
  std::chrono::milliseconds period_;
  uint64_t sent_ = 0;
};

}  // namespace hexplore::testing
