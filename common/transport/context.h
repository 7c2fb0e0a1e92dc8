#pragma once
// One ZeroMQ context per process (inproc endpoints only connect within one context), and the
// identity a socket stamps on every header it sends.

#include <memory>
#include <string>

#include <zmq.hpp>

#include "common/transport/curve_guard.h"

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

  ~Context();

  zmq::context_t& zmq() { return context_; }

  // Starts the ZAP handler that admits only the keyring's members to this process's CURVE
  // servers; needed before a socket with SocketOptions::curve binds on tcp. Once per context.
  void enable_curve(std::shared_ptr<const CurveKeyring> keyring, CurveGuard::OnRefused on_refused = {});
  CurveGuard* curve_guard() { return guard_.get(); }

 private:
  zmq::context_t context_;
  std::unique_ptr<CurveGuard> guard_;  // closed before context_ terminates
};

}  // namespace hexplore::transport
