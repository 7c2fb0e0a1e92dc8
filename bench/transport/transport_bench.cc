// Transport benchmark between two processes over tcp loopback: one-way throughput of
// 200-byte payloads (sent back to back) and one-way latency at 1,000 msg/s (p50/p99/max,
// wall clock send -> receive, both processes on one host). The parent publishes; it starts
// a copy of itself (--sink) that subscribes and prints the receiving side's figures.
//
//   transport_bench [--count N] [--latency-seconds S] [--payload-bytes B] [--wire-only true]
//                   [--curve DIR]
// --curve DIR: both ends on authenticated, encrypted links (ZeroMQ CURVE), with key pairs for
// "source" and "sink" made in DIR when missing: the cost of team links with keys.
// It first prints the bytes typical team messages take on the radio, schema v1 against v2
// (team_message_bytes.h); --wire-only true stops there.

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "bench/transport/team_message_bytes.h"
#include "common/core/clock.h"
#include "common/metrics/prometheus_registry.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/test_messages.pb.h"

namespace {

using namespace hexplore;
using namespace std::chrono_literals;

struct Args {
  uint64_t count = 1'000'000;
  int latency_seconds = 5;
  size_t payload_bytes = 200;
  std::string sink_endpoint;  // non-empty: run as the receiving child
  std::string curve_dir;      // non-empty: CURVE with the pairs in this folder
};

// `member`'s CURVE credentials from args.curve_dir (pairs made for both ends when missing);
// null without --curve.
std::shared_ptr<const transport::CurveCredentials> bench_curve(const Args& args, const std::string& member) {
  if (args.curve_dir.empty()) return nullptr;
  transport::write_missing_curve_key_pairs(args.curve_dir, {"source", "sink"});
  const auto ring = transport::CurveKeyring::load(args.curve_dir, {"source", "sink"});
  return std::make_shared<transport::CurveCredentials>(transport::CurveCredentials{member, ring->own_pair(member), ring});
}

transport::SocketOptions bench_options() {
  transport::SocketOptions options;
  // Deep queues so that the back-to-back phase measures speed, not high-water-mark drops.
  options.send_high_water_mark = 2'000'000;
  options.receive_high_water_mark = 2'000'000;
  return options;
}

double percentile(std::vector<int64_t>& values, double p) {
  if (values.empty()) return 0.0;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(p * static_cast<double>(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return static_cast<double>(values[k]);
}

int run_sink(const Args& args) {
  metrics::PrometheusRegistry registry;
  const auto families = metrics::TransportFamilies::create(registry);
  transport::Context context;
  transport::Accounting accounting("sink", "bench", &families);
  transport::SocketOptions options = bench_options();
  options.curve = bench_curve(args, "sink");
  transport::Subscriber subscriber(context, options, &accounting);
  transport::EventLoop loop;
  bool subscribed = false;
  uint64_t received = 0;
  int64_t first_ns = 0, last_ns = 0;
  bool throughput_reported = false;
  std::vector<int64_t> latencies;
  latencies.reserve(100'000);

  auto report_throughput = [&] {
    if (throughput_reported || received == 0) return;
    throughput_reported = true;
    const double seconds = core::ns_to_s(last_ns - first_ns);
    const double rate = seconds > 0 ? static_cast<double>(received - 1) / seconds : 0.0;
    std::printf("sink: throughput received %llu of %llu messages (%.2f%% lost) in %.3f s: %.0f msg/s, %.1f MB/s of payload\n",
                static_cast<unsigned long long>(received), static_cast<unsigned long long>(args.count),
                100.0 * (1.0 - static_cast<double>(received) / static_cast<double>(args.count)), seconds, rate,
                rate * static_cast<double>(args.payload_bytes) / 1e6);
    std::fflush(stdout);
  };

  subscriber.on<v1::TestPayload>("bench/probe", [&](const transport::Received<v1::TestPayload>&) {
    if (subscribed) return;
    subscribed = true;
    std::printf("subscribed\n");
    std::fflush(stdout);
  });
  subscriber.on<v1::TestPayload>("bench/throughput", [&](const transport::Received<v1::TestPayload>& m) {
    last_ns = core::monotonic_ns();
    if (received++ == 0) first_ns = last_ns;
    if (m.message.counter() == args.count) report_throughput();
  });
  subscriber.on<v1::TestPayload>("bench/latency", [&](const transport::Received<v1::TestPayload>& m) {
    report_throughput();  // in case the last throughput message was lost
    latencies.push_back(core::wall_time_ns() - m.header.send_time_ns());
  });
  subscriber.on<v1::TestPayload>("bench/done", [&](const transport::Received<v1::TestPayload>&) {
    report_throughput();
    const size_t n = latencies.size();
    const double p50 = percentile(latencies, 0.50), p99 = percentile(latencies, 0.99),
                 max = n ? static_cast<double>(*std::max_element(latencies.begin(), latencies.end())) : 0.0;
    std::printf("sink: latency over %zu messages at 1000 msg/s: p50 %.1f us, p99 %.1f us, max %.1f us\n", n, p50 / 1e3,
                p99 / 1e3, max / 1e3);
    std::printf("sink: accounting received %llu messages, %llu bytes (incl. topic and header frames)\n",
                static_cast<unsigned long long>(accounting.received_all().messages),
                static_cast<unsigned long long>(accounting.received_all().bytes));
    std::fflush(stdout);
    loop.stop();
  });
  subscriber.connect(args.sink_endpoint, "source");
  loop.add(subscriber);
  loop.run();
  return 0;
}

// Reads the child's stdout, echoing it, until a line contains `needle` or `timeout` passes.
bool wait_for_child_line(int fd, std::string& buffer, const char* needle, std::chrono::milliseconds timeout,
                         const std::function<void()>& between = {}) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    for (size_t nl; (nl = buffer.find('\n')) != std::string::npos;) {
      const std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      if (line != "subscribed") std::printf("%s\n", line.c_str());
      if (line.find(needle) != std::string::npos) return true;
    }
    if (between) between();
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 5) > 0) {
      char chunk[1024];
      const ssize_t n = read(fd, chunk, sizeof(chunk));
      if (n <= 0) return false;
      buffer.append(chunk, static_cast<size_t>(n));
    }
  }
  return false;
}

int run_source(const Args& args, const char* self) {
  metrics::PrometheusRegistry registry;
  const auto families = metrics::TransportFamilies::create(registry);
  transport::Context context;
  transport::Accounting accounting("source", "bench", &families);
  transport::SocketOptions options = bench_options();
  options.curve = bench_curve(args, "source");
  if (options.curve) context.enable_curve(options.curve->keyring);
  transport::Publisher publisher(context, transport::Identity{"source", "", "bench"}, "tcp://127.0.0.1:*", options,
                                 &accounting);

  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return 1;
  const std::string count = std::to_string(args.count), bytes = std::to_string(args.payload_bytes);
  const pid_t child = fork();
  if (child == 0) {
    dup2(fds[1], STDOUT_FILENO);
    const char* curve = args.curve_dir.empty() ? nullptr : "--curve";  // ends the list without --curve
    execl(self, self, "--sink", publisher.endpoint().c_str(), "--count", count.c_str(), "--payload-bytes",
          bytes.c_str(), curve, args.curve_dir.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  std::string buffer;
  v1::TestPayload message;
  message.set_blob(std::string(args.payload_bytes, 'b'));
  message.set_counter(0);
  if (!wait_for_child_line(fds[0], buffer, "subscribed", 10s, [&] { publisher.publish("bench/probe", message); })) {
    std::fprintf(stderr, "error: the sink process never subscribed\n");
    return 1;
  }
  message.set_counter(args.count);
  std::printf("transport_bench: tcp loopback%s, %zu-byte blob (%zu-byte TestPayload, plus topic and Header frames)\n",
              options.curve ? " with CURVE" : "", args.payload_bytes, message.ByteSizeLong());

  // Phase 1: back-to-back.
  const int64_t start = core::monotonic_ns();
  for (uint64_t i = 1; i <= args.count; ++i) {
    message.set_counter(i);
    publisher.publish("bench/throughput", message);
  }
  const double send_s = core::ns_to_s(core::monotonic_ns() - start);
  std::printf("source: published %llu messages in %.3f s: %.0f msg/s\n", static_cast<unsigned long long>(args.count),
              send_s, static_cast<double>(args.count) / send_s);
  std::fflush(stdout);
  if (!wait_for_child_line(fds[0], buffer, "throughput", 60s)) std::printf("source: no throughput report from the sink\n");

  // Phase 2: 1,000 msg/s on a fixed schedule.
  auto next = std::chrono::steady_clock::now();
  const uint64_t latency_count = static_cast<uint64_t>(args.latency_seconds) * 1000;
  for (uint64_t i = 1; i <= latency_count; ++i) {
    next += 1ms;
    std::this_thread::sleep_until(next);
    message.set_counter(i);
    publisher.publish("bench/latency", message);
  }
  std::this_thread::sleep_for(50ms);
  publisher.publish("bench/done", message);
  wait_for_child_line(fds[0], buffer, "accounting", 30s);
  std::printf("source: accounting sent %llu messages, %llu bytes\n",
              static_cast<unsigned long long>(accounting.sent_all().messages),
              static_cast<unsigned long long>(accounting.sent_all().bytes));
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bool wire_only = false;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const char* value = argv[i + 1];
    if (flag == "--count") args.count = std::stoull(value);
    else if (flag == "--latency-seconds") args.latency_seconds = std::stoi(value);
    else if (flag == "--payload-bytes") args.payload_bytes = std::stoul(value);
    else if (flag == "--sink") args.sink_endpoint = value;
    else if (flag == "--wire-only") wire_only = std::string(value) == "true";
    else if (flag == "--curve") args.curve_dir = value;
    else {
      std::fprintf(stderr,
                   "error: unknown flag %s\nusage: %s [--count N] [--latency-seconds S] [--payload-bytes B] "
                   "[--wire-only true] [--curve DIR]\n",
                   flag.c_str(), argv[0]);
      return 2;
    }
  }
  if (!args.sink_endpoint.empty()) return run_sink(args);
  hexplore::bench::print_team_message_bytes();
  if (wire_only) return 0;
  return run_source(args, "/proc/self/exe");
}
