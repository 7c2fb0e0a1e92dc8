#pragma once
// What the EventLoop needs from a socket wrapper: the socket to poll for input, how to take
// waiting messages off it, and an optional deadline (delayed sends, request time-outs).

#include <cstddef>
#include <cstdint>
#include <optional>

#include <zmq.hpp>

namespace hexplore::transport {

class Pollable {
 public:
  virtual ~Pollable() = default;
  // Socket to poll for input; nullptr when the wrapper only has deadlines (a Publisher).
  virtual zmq::socket_t* input_socket() = 0;
  // Handles up to `max` waiting messages without blocking; returns how many were taken.
  virtual size_t drain(size_t max) = 0;
  // Earliest steady-clock time (core::monotonic_ns) at which on_deadline() has work.
  virtual std::optional<int64_t> next_deadline_ns() const { return std::nullopt; }
  virtual void on_deadline(int64_t now_ns) {}
};

}  // namespace hexplore::transport
