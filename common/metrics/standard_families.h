#pragma once
// The metric families every hexplore process exports, created once per registry. Labels:
// robot (own id), service, topic (bounded: robot ids appear only for team members), peer
// (sending robot id), reason (a fixed enum).

#include <cstdint>
#include <string>

#include "common/metrics/registry.h"

namespace hexplore::metrics {

// Transport accounting (see common/transport/accounting.h for who records what).
struct TransportFamilies {
  CounterFamily* sent_messages = nullptr;      // {robot,service,topic,peer}
  CounterFamily* sent_bytes = nullptr;         // {robot,service,topic,peer}
  CounterFamily* received_messages = nullptr;  // {robot,service,topic,peer}
  CounterFamily* received_bytes = nullptr;     // {robot,service,topic,peer}
  CounterFamily* dropped = nullptr;            // {robot,service,topic,reason}
  HistogramFamily* latency = nullptr;          // {robot,service,topic}, seconds

  // Registers (or finds) the families in `registry`.
  static TransportFamilies create(Registry& registry);
};

// Process up-time and CPU time, refreshed by update() (the service base calls it on a timer).
class ProcessMetrics {
 public:
  ProcessMetrics(Registry& registry, const std::string& robot, const std::string& service);
  void update();

 private:
  int64_t start_ns_;
  Gauge* uptime_s_;
  Counter* cpu_s_;
  double cpu_reported_s_ = 0.0;
};

// CPU time (user + system) this process has used so far, in seconds.
double process_cpu_seconds();

}  // namespace hexplore::metrics
