#pragma once
// What the EventLoop needs from a socket wrapper: the socket to poll for input, how to handle
// one received message, and an optional deadline (delayed sends, request time-outs).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <zmq.hpp>

#include "common/transport/loop_clock.h"

namespace hexplore::transport {

class Pollable {
 public:
  virtual ~Pollable() = default;
  // Socket to poll for input; nullptr when the wrapper only has deadlines (a Publisher).
  virtual zmq::socket_t* input_socket() = 0;
  // The wrapper's socket, input or not: lockstep brings its ZeroMQ state up to date before sends.
  virtual zmq::socket_t* socket() { return input_socket(); }
  // Handles one multipart message received on input_socket().
  virtual void handle(std::vector<zmq::message_t>& frames) {}
  // Which frame of a received message holds the Header (-1: none). Lockstep orders the
  // messages of one step by the sender named there.
  virtual int header_frame() const { return -1; }
  // Receives and handles up to `max` waiting messages without blocking; returns how many were taken.
  size_t drain(size_t max);

  // Earliest time (on the clock, see set_clock) at which on_deadline() has work.
  virtual std::optional<int64_t> next_deadline_ns() const { return std::nullopt; }
  virtual void on_deadline(int64_t now_ns) {}
  // The clock deadlines are set and checked on; EventLoop::add sets the loop's. Without one: monotonic.
  void set_clock(const LoopClock* clock) { clock_ = clock; }

 protected:
  int64_t now_ns() const { return clock_ ? clock_->now_ns() : core::monotonic_ns(); }
  // Names the wrapper in receive-failure logs ("subscriber", ...).
  virtual const char* role() const = 0;

 private:
  const LoopClock* clock_ = nullptr;
};

}  // namespace hexplore::transport
