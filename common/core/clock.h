#pragma once
// Time sources. Wall time stamps envelopes (latency); sim time is what payloads refer to.

#include <chrono>
#include <cstdint>

namespace hexplore::core {

// Nanoseconds since the Unix epoch (system clock): comparable across processes on one host.
inline int64_t wall_time_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Nanoseconds of a monotonic clock, for measuring durations inside one process.
inline int64_t monotonic_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

inline double ns_to_s(int64_t ns) { return static_cast<double>(ns) * 1e-9; }
inline int64_t s_to_ns(double s) { return static_cast<int64_t>(s * 1e9); }

}  // namespace hexplore::core
