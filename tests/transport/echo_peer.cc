// Test helper process for the cross-process transport tests. It binds a PUB and a ROUTER on
// ephemeral tcp ports and prints them, exposes /metrics on an ephemeral port, echoes every
// TestPayload it receives on robot/<any>/<leaf> back as robot/<me>/<leaf>_echo, and on a
// TestPayload request {counter = N, blob of B bytes} publishes N messages of B bytes on
// robot/<me>/burst. SIGTERM/SIGINT stop it cleanly (queued messages are flushed).
//
//   echo_peer --robot ID [--connect ENDPOINT] [--drop FRACTION --fault-prefix PREFIX] [--delay-ms N]

#include <signal.h>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "common/core/log.h"
#include "common/metrics/prometheus_registry.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"
#include "hexplore/v1/test_messages.pb.h"

namespace {

hexplore::transport::EventLoop* g_loop = nullptr;  // for the signal handler only

void on_signal(int) {
  if (g_loop != nullptr) g_loop->stop();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hexplore;
  std::string robot = "r2";
  std::string connect;
  transport::FaultInjection faults;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--robot") robot = value;
    else if (flag == "--connect") connect = value;
    else if (flag == "--drop") faults.drop_fraction = std::stod(value);
    else if (flag == "--fault-prefix") faults.topic_prefixes.push_back(value);
    else if (flag == "--delay-ms") faults.delay = std::chrono::milliseconds(std::stoi(value));
    else {
      std::cerr << "error: unknown flag " << flag << "\n";
      return 2;
    }
  }

  metrics::PrometheusRegistry registry;
  const auto families = metrics::TransportFamilies::create(registry);
  {
    transport::Context context;
    transport::Accounting accounting(robot, "echo", &families);
    transport::SocketOptions pub_options;
    pub_options.faults = faults;
    const transport::Identity identity{robot, "test", "echo"};
    transport::Publisher publisher(context, identity, "tcp://127.0.0.1:*", pub_options, &accounting);
    transport::Responder responder(context, identity, "tcp://127.0.0.1:*", {}, &accounting);
    transport::Subscriber subscriber(context, {}, &accounting);
    transport::EventLoop loop;
    g_loop = &loop;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);

    const std::string own_prefix = transport::topics::robot_prefix(robot);
    subscriber.on<v1::TestPayload>("robot/", [&](const transport::Received<v1::TestPayload>& m) {
      if (m.topic.substr(0, own_prefix.size()) == own_prefix) return;
      const std::string leaf(m.topic.substr(m.topic.rfind('/') + 1));
      publisher.publish(transport::topics::robot_topic(robot, leaf + "_echo"), m.message);
    });
    if (!connect.empty()) subscriber.connect(connect);

    responder.serve<v1::TestPayload, v1::TestPayload>([&](const transport::Received<v1::TestPayload>& request) {
      const uint64_t count = request.message.counter();
      const size_t bytes = request.message.blob().size();
      loop.post([&publisher, robot, count, bytes] {
        v1::TestPayload message;
        message.set_blob(std::string(bytes, 'x'));
        const std::string topic = transport::topics::robot_topic(robot, "burst");
        for (uint64_t i = 1; i <= count; ++i) {
          message.set_counter(i);
          publisher.publish(topic, message);
        }
        std::printf("burst-sent %llu\n", static_cast<unsigned long long>(count));
        std::fflush(stdout);
      });
      v1::TestPayload reply;
      reply.set_counter(count);
      return reply;
    });

    loop.add(subscriber);
    loop.add(responder);
    loop.add(publisher);
    const int port = registry.expose(0, "127.0.0.1");
    std::printf("pub %s\nreq %s\nmetrics %d\nready\n", publisher.endpoint().c_str(), responder.endpoint().c_str(), port);
    std::fflush(stdout);
    loop.run();
    std::printf("stopping sent=%llu\n", static_cast<unsigned long long>(accounting.sent_all().messages));
    std::fflush(stdout);
    g_loop = nullptr;
  }  // publisher flushes delayed messages; the context waits up to linger for the queue to drain
  return 0;
}
