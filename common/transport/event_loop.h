#pragma once
// A single-threaded poll loop: serves several sockets (subscribers, responders, requesters),
// periodic timers and socket deadlines (delayed sends, request time-outs) with zmq::poll.
// stop() and post() may be called from any thread; stop() also from a signal handler.
//
// Lockstep (the reproducible fast mode): instead of run(), a driver (service::ServiceHost)
// calls collect() and dispatch() on every loop of a process in turn, on a virtual clock. The
// messages of one step are then handled in an order that does not depend on thread timing:
// by socket in registration order, then by sender, each sender's messages in sending order.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <mutex>
#include <vector>

#include <zmq.h>

#include "common/transport/loop_clock.h"
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

  // The time timers and deadlines run on (monotonic, or virtual in lockstep). Loop thread only.
  int64_t now_ns() const { return clock_.now_ns(); }
  bool in_lockstep() const { return clock_.is_virtual(); }

  // Lockstep, loop thread only. enter_lockstep() makes the clock virtual at 0 (call before
  // timers are added). collect() takes every waiting message off every input socket without
  // handling it and returns how many; discard_collected() forgets them. dispatch() sets the
  // clock to `now_ns`, handles what collect() took, runs posted functions and, with
  // `run_due`, the deadlines and timers due by then. next_due_ns(): the earliest timer or
  // deadline still to come.
  void enter_lockstep();
  size_t collect();
  void discard_collected();
  void dispatch(int64_t now_ns, bool run_due);
  std::optional<int64_t> next_due_ns() const;

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
  void run_deadlines(int64_t now_ns);

  // A message taken off a socket by collect(), waiting for dispatch().
  struct Held {
    size_t socket_index;  // position in sockets_ at collect time
    std::string sender;   // the sender bytes of the header (header_sender_key); "" when unreadable
    Pollable* socket;
    std::vector<zmq::message_t> frames;
  };

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
  LoopClock clock_;
  std::vector<Held> held_;
};

}  // namespace hexplore::transport
