#pragma once
// One ZeroMQ context per process (inproc endpoints only connect within one context), and the
// identity a socket stamps on every header it sends.

#include <string>

#include <zmq.hpp>

namespace hexplore::transport {

// Who is sending: copied into every outgoing Header.
struct Identity {
  std::string robot_id;  // "station" for the ground station
  std::string species;   // "" for the station
  std::string service;   // "sim", "mapping", "hlmap", "planning", "safety", "station", or a tool name
};

// Owns the zmq::context_t. Destroy it after every socket made from it; destruction waits at
// most each socket's linger for queued messages to leave.
class Context {
 public:
  explicit Context(int io_threads = 1);
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  zmq::context_t& zmq() { return context_; }

 private:
  zmq::context_t context_;
};

}  // namespace hexplore::transport
