#include "common/transport/event_loop.h"

#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include <zmq.hpp>

#include "common/core/clock.h"
#include "common/core/log.h"

namespace hexplore::transport {

EventLoop::EventLoop() : wake_fd_(eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  if (wake_fd_ < 0) throw std::system_error(errno, std::generic_category(), "transport: eventfd for EventLoop");
}

EventLoop::~EventLoop() { close(wake_fd_); }

void EventLoop::add(Pollable& socket) {
  if (std::find(sockets_.begin(), sockets_.end(), &socket) == sockets_.end()) sockets_.push_back(&socket);
  items_dirty_ = true;
}

void EventLoop::remove(Pollable& socket) {
  sockets_.erase(std::remove(sockets_.begin(), sockets_.end(), &socket), sockets_.end());
  items_dirty_ = true;
}

EventLoop::TimerId EventLoop::add_timer(std::chrono::nanoseconds period, std::function<void()> fn) {
  if (period.count() <= 0) throw std::invalid_argument("transport: timer period must be > 0");
  const TimerId id = next_timer_id_++;
  timers_.emplace(id, Timer{period, core::monotonic_ns() + period.count(), std::move(fn)});
  return id;
}

void EventLoop::cancel_timer(TimerId id) { timers_.erase(id); }

void EventLoop::post(std::function<void()> fn) {
  {
    std::lock_guard lock(posted_mutex_);
    posted_.push_back(std::move(fn));
  }
  const uint64_t one = 1;
  [[maybe_unused]] ssize_t n = write(wake_fd_, &one, sizeof(one));
}

void EventLoop::stop() {
  stop_.store(true);
  const uint64_t one = 1;
  [[maybe_unused]] ssize_t n = write(wake_fd_, &one, sizeof(one));
}

void EventLoop::reset() { stop_.store(false); }

void EventLoop::run_posted() {
  std::vector<std::function<void()>> batch;
  {
    std::lock_guard lock(posted_mutex_);
    batch.swap(posted_);
  }
  for (auto& fn : batch) fn();
}

void EventLoop::run_timers(int64_t now_ns) {
  // Collect due ids first: a callback may add or cancel timers.
  std::vector<TimerId> due;
  for (const auto& [id, timer] : timers_)
    if (timer.next_ns <= now_ns) due.push_back(id);
  for (TimerId id : due) {
    auto it = timers_.find(id);
    if (it == timers_.end()) continue;
    Timer& t = it->second;
    t.next_ns += t.period.count();
    if (t.next_ns <= now_ns) t.next_ns = now_ns + t.period.count();  // fell behind: skip, don't burst
    auto fn = t.fn;  // copy: the callback may cancel its own timer
    fn();
    if (stop_.load()) return;
  }
}

void EventLoop::iterate(int64_t max_wait_ns) {
  int64_t now = core::monotonic_ns();
  int64_t wait_ns = max_wait_ns;
  for (const auto& [id, timer] : timers_) wait_ns = std::min(wait_ns, timer.next_ns - now);
  for (Pollable* p : sockets_)
    if (auto deadline = p->next_deadline_ns()) wait_ns = std::min(wait_ns, *deadline - now);
  wait_ns = std::max<int64_t>(wait_ns, 0);

  if (items_dirty_) {
    items_.clear();
    readers_.clear();
    items_.push_back(zmq_pollitem_t{nullptr, wake_fd_, ZMQ_POLLIN, 0});
    for (Pollable* p : sockets_) {
      if (zmq::socket_t* s = p->input_socket()) {
        items_.push_back(zmq_pollitem_t{static_cast<void*>(*s), 0, ZMQ_POLLIN, 0});
        readers_.push_back(p);
      }
    }
    items_dirty_ = false;
  }
  std::vector<zmq_pollitem_t>& items = items_;
  // Round up to whole milliseconds (zmq::poll's unit) so that a timer is never polled early in a busy loop.
  const auto timeout = std::chrono::milliseconds((wait_ns + 999'999) / 1'000'000);
  try {
    zmq::poll(items.data(), items.size(), timeout);
  } catch (const zmq::error_t& e) {
    if (e.num() == EINTR) return;
    if (e.num() == ETERM) {
      stop_.store(true);
      return;
    }
    throw;
  }
  if (items[0].revents & ZMQ_POLLIN) {
    uint64_t value = 0;
    [[maybe_unused]] ssize_t n = read(wake_fd_, &value, sizeof(value));
  }
  // A callback that adds or removes a socket marks the poll set dirty; the rest of this round
  // is then skipped (ZeroMQ readiness is level-triggered, so nothing is lost, only deferred).
  run_posted();
  for (size_t i = 0; i < readers_.size() && !stop_.load() && !items_dirty_; ++i)
    if (items[i + 1].revents & ZMQ_POLLIN) readers_[i]->drain(256);
  if (stop_.load()) return;
  now = core::monotonic_ns();
  for (size_t i = 0; i < sockets_.size() && !items_dirty_; ++i)
    if (auto deadline = sockets_[i]->next_deadline_ns(); deadline && *deadline <= now) sockets_[i]->on_deadline(now);
  run_timers(now);
}

void EventLoop::run() {
  while (!stop_.load()) iterate(1'000'000'000);
  run_posted();
}

bool EventLoop::run_until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const int64_t end_ns = core::monotonic_ns() + std::chrono::nanoseconds(timeout).count();
  while (!stop_.load() && !done()) {
    const int64_t left = end_ns - core::monotonic_ns();
    if (left <= 0) break;
    // Wake at least every 10 ms so done() is re-checked even without traffic.
    iterate(std::min<int64_t>(left, 10'000'000));
  }
  return done();
}

}  // namespace hexplore::transport
