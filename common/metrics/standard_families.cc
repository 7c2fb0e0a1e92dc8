#include "common/metrics/standard_families.h"

#include <sys/resource.h>

#include <chrono>

namespace hexplore::metrics {

TransportFamilies TransportFamilies::create(Registry& r) {
  TransportFamilies f;
  f.sent_messages = r.counter_family("hexplore_transport_sent_messages_total", "Messages sent, per topic and peer");
  f.sent_bytes = r.counter_family("hexplore_transport_sent_bytes_total",
                                  "Bytes sent (topic + header + payload frames), per topic and peer");
  f.received_messages =
      r.counter_family("hexplore_transport_received_messages_total", "Messages accepted, per topic and peer");
  f.received_bytes = r.counter_family("hexplore_transport_received_bytes_total",
                                      "Bytes accepted (topic + header + payload frames), per topic and peer");
  f.dropped = r.counter_family("hexplore_transport_dropped_total",
                               "Messages dropped, by reason (malformed, wrong_version, wrong_type, oversize, "
                               "fault_injected, timeout, send_failed, handler_error)");
  f.latency = r.histogram_family("hexplore_transport_latency_seconds",
                                 "Receive wall time minus the sender's header send time", latency_buckets_s());
  return f;
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

namespace {
int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

ProcessMetrics::ProcessMetrics(Registry& registry, const std::string& robot, const std::string& service)
    : start_ns_(steady_ns()),
      uptime_s_(registry.gauge_family("hexplore_process_uptime_seconds", "Seconds since the service started")
                    ->add({{"robot", robot}, {"service", service}})),
      cpu_s_(registry.counter_family("hexplore_process_cpu_seconds_total", "CPU time (user + system) of the process")
                 ->add({{"robot", robot}, {"service", service}})) {
  update();
}

void ProcessMetrics::update() {
  uptime_s_->set(static_cast<double>(steady_ns() - start_ns_) * 1e-9);
  const double cpu = process_cpu_seconds();
  if (cpu > cpu_reported_s_) {
    cpu_s_->increment(cpu - cpu_reported_s_);
    cpu_reported_s_ = cpu;
  }
}

}  // namespace hexplore::metrics
