#pragma once
// A single-threaded poll loop: serves several sockets (subscribers, responders, requesters),
// periodic timers and socket deadlines (delayed sends, request time-outs) with zmq::poll.
// stop() and post() may be called from any thread; stop() also from a signal handler.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <vector>

#include <zmq.h>

#include "common/transport/pollable.h"

namespace hexplore::transport {

class EventLoop {
 public:
  using TimerId = uint64_t;

  EventLoop();
  ~EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  // Registers a socket wrapper (Subscriber, Responder, Requester, Publisher). It must outlive
  // the loop's run() or be removed first. Call from the loop thread or before run().
  void add(Pollable& socket);
  void remove(Pollable& socket);

  // Calls `fn` every `period` (first call one period from now) until cancelled. A timer that
  // falls behind skips missed ticks instead of bursting. Loop thread only (or before run()).
  TimerId add_timer(std::chrono::nanoseconds period, std::function<void()> fn);
  void cancel_timer(TimerId id);

  // Runs `fn` on the loop thread at its next iteration. Thread-safe.
  void post(std::function<void()> fn);

  // Runs until stop(). Returns after the current callback finishes.
  void run();
  // Runs until `done()` is true (checked after each iteration) or `timeout` passes, or stop();
  // returns done(). For tests and tools.
  bool run_until(const std::function<bool()>& done, std::chrono::milliseconds timeout);
  // Asks run() to return. Thread-safe and async-signal-safe (an atomic store and a write()).
  void stop();
  bool stop_requested() const { return stop_.load(); }
  // Clears a previous stop() so the loop can run again.
  void reset();

 private:
  struct Timer {
    std::chrono::nanoseconds period;
    int64_t next_ns;
    std::function<void()> fn;
  };
  // One poll + dispatch round, waiting at most `max_wait_ns`.
  void iterate(int64_t max_wait_ns);
  void run_posted();
  void run_timers(int64_t now_ns);

  std::vector<Pollable*> sockets_;
  // Poll set rebuilt only when sockets are added or removed: [wake fd, input sockets...].
  std::vector<zmq_pollitem_t> items_;
  std::vector<Pollable*> readers_;
  bool items_dirty_ = true;
  std::map<TimerId, Timer> timers_;
  TimerId next_timer_id_ = 1;
  std::atomic<bool> stop_{false};
  int wake_fd_;  // eventfd: stop() and post() wake a blocked poll
  std::mutex posted_mutex_;
  std::vector<std::function<void()>> posted_;
};

}  // namespace hexplore::transport
