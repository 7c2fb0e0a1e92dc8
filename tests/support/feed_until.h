#pragma once
// Service-level tests drive a service over sockets: keep feeding its inputs (late-joining
// subscriptions miss the first messages) and pumping its outputs in 50 ms steps until a
// condition on the outputs holds, or a limit passes. Header-only, for tests.

#include <chrono>
#include <functional>

namespace hexplore::testing {

// Repeats: feed(), then pump() for ~50 ms, then check done(). True once done() holds.
inline bool feed_until(const std::function<void()>& feed, const std::function<void()>& pump,
                       const std::function<bool()>& done, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    feed();
    const auto step_end = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
    while (std::chrono::steady_clock::now() < step_end) pump();
    if (done()) return true;
  }
  return false;
}

}  // namespace hexplore::testing
