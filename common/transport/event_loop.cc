#include "common/transport/event_loop.h"

#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include <zmq.hpp>

#include "common/core/clock.h"
#include "common/core/log.h"
#include "common/transport/envelope.h"
#include "common/transport/socket_util.h"
#include "hexplore/v1/header.pb.h"

namespace hexplore::transport {

EventLoop::EventLoop() : wake_fd_(eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  if (wake_fd_ < 0) throw std::system_error(errno, std::generic_category(), "transport: eventfd for EventLoop");
}

EventLoop::~EventLoop() { close(wake_fd_); }

void EventLoop::add(Pollable& socket) {
  if (std::find(sockets_.begin(), sockets_.end(), &socket) == sockets_.end()) sockets_.push_back(&socket);
  socket.set_clock(&clock_);
  items_dirty_ = true;
}

void EventLoop::remove(Pollable& socket) {
  sockets_.erase(std::remove(sockets_.begin(), sockets_.end(), &socket), sockets_.end());
  items_dirty_ = true;
}

EventLoop::TimerId EventLoop::add_timer(std::chrono::nanoseconds period, std::function<void()> fn) {
  if (period.count() <= 0) throw std::invalid_argument("transport: timer period must be > 0");
  const TimerId id = next_timer_id_++;
  timers_.emplace(id, Timer{period, clock_.now_ns() + period.count(), std::move(fn)});
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

void EventLoop::run_deadlines(int64_t now_ns) {
  // A snapshot: a deadline callback may add or remove sockets.
  const std::vector<Pollable*> sockets = sockets_;
  for (Pollable* p : sockets) {
    if (std::find(sockets_.begin(), sockets_.end(), p) == sockets_.end()) continue;
    if (auto deadline = p->next_deadline_ns(); deadline && *deadline <= now_ns) p->on_deadline(now_ns);
  }
}

void EventLoop::iterate(int64_t max_wait_ns) {
  int64_t now = clock_.now_ns();
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
  now = clock_.now_ns();
  run_deadlines(now);
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

// ---- lockstep ------------------------------------------------------------------------------

void EventLoop::enter_lockstep() { clock_.make_virtual(0); }

size_t EventLoop::collect() {
  size_t taken = 0;
  for (size_t i = 0; i < sockets_.size(); ++i) {
    zmq::socket_t* socket = sockets_[i]->input_socket();
    if (socket == nullptr) continue;
    const int at = sockets_[i]->header_frame();
    Held held{i, {}, sockets_[i], {}};
    while (detail::receive_frames(*socket, held.frames, "lockstep")) {
      if (at >= 0 && static_cast<size_t>(at) < held.frames.size())
        held.sender = std::string(header_sender_key(held.frames[at].data(), held.frames[at].size()));
      held_.push_back(std::move(held));
      held = Held{i, {}, sockets_[i], {}};
      ++taken;
    }
  }
  return taken;
}

void EventLoop::discard_collected() { held_.clear(); }

void EventLoop::dispatch(int64_t now_ns, bool run_due) {
  clock_.set(now_ns);
  // Bring every socket's ZeroMQ state up to date (subscriptions, pipe capacity): all reads of
  // this step happened in collect(), so what a send sees no longer depends on thread timing.
  for (Pollable* p : sockets_)
    if (zmq::socket_t* s = p->socket()) (void)s->get(zmq::sockopt::events);
  // Stable: one sender's messages keep the order ZeroMQ delivered them in (its sending order).
  std::stable_sort(held_.begin(), held_.end(), [](const Held& a, const Held& b) {
    return a.socket_index != b.socket_index ? a.socket_index < b.socket_index : a.sender < b.sender;
  });
  std::vector<Held> batch;
  batch.swap(held_);
  for (Held& h : batch) {
    if (stop_.load()) return;
    // A callback may have removed the socket since collect().
    if (std::find(sockets_.begin(), sockets_.end(), h.socket) == sockets_.end()) continue;
    h.socket->handle(h.frames);
  }
  run_posted();
  if (!run_due || stop_.load()) return;
  run_deadlines(now_ns);
  run_timers(now_ns);
}

std::optional<int64_t> EventLoop::next_due_ns() const {
  std::optional<int64_t> next;
  for (const auto& [id, timer] : timers_)
    if (!next || timer.next_ns < *next) next = timer.next_ns;
  for (const Pollable* p : sockets_)
    if (auto deadline = p->next_deadline_ns(); deadline && (!next || *deadline < *next)) next = deadline;
  return next;
}

}  // namespace hexplore::transport
