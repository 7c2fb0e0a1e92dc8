#pragma once
// The time an EventLoop's timers and socket deadlines run on: the monotonic clock, or, in
// lockstep (the reproducible fast mode), a virtual time that only the loop's driver advances.

#include <cstdint>

#include "common/core/clock.h"

namespace hexplore::transport {

class LoopClock {
 public:
  int64_t now_ns() const { return virtual_ ? virtual_now_ns_ : core::monotonic_ns(); }
  bool is_virtual() const { return virtual_; }
  // From now on the clock stands at `start_ns` until set() moves it.
  void make_virtual(int64_t start_ns) {
    virtual_ = true;
    virtual_now_ns_ = start_ns;
  }
  void set(int64_t now_ns) { virtual_now_ns_ = now_ns; }

 private:
  bool virtual_ = false;
  int64_t virtual_now_ns_ = 0;
};

}  // namespace hexplore::transport
