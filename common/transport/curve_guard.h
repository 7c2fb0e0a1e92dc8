#pragma once
// The gatekeeper of a process's CURVE servers: ZeroMQ asks a ZAP handler (RFC 27, on
// inproc://zeromq.zap.01 of the same context) whether a client that completed the CURVE
// handshake may connect. The guard answers yes only for a public key of the team's keyring and
// names the peer by its member (the messages it sends then carry that name as their User-Id).
// Every refused peer is counted and logged once per key. It also watches the server sockets
// it is given for handshakes that fail before the ZAP stage (a client without keys, or with
// the wrong server key), which are counted as well.
//
// One thread, started by the constructor and joined by the destructor; destroy the guard
// before the context (transport::Context does).

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <zmq.hpp>

#include "common/transport/curve_keys.h"

namespace hexplore::transport {

class CurveGuard {
 public:
  // Why a peer was refused.
  enum class Refusal { kUnknownKey, kHandshake };
  // Called on the guard's thread for every refused peer (`what`: the Z85 key or the failure).
  using OnRefused = std::function<void(Refusal reason, const std::string& what)>;

  CurveGuard(zmq::context_t& context, std::shared_ptr<const CurveKeyring> keyring, OnRefused on_refused = {});
  ~CurveGuard();
  CurveGuard(const CurveGuard&) = delete;
  CurveGuard& operator=(const CurveGuard&) = delete;

  // Reports the handshakes that fail on `socket` (a CURVE server). Call from the thread that
  // owns the socket, before it accepts peers.
  void watch(zmq::socket_t& socket);

  uint64_t refused() const { return refused_.load(); }
  uint64_t accepted() const { return accepted_.load(); }

 private:
  void run();
  void answer(zmq::socket_t& zap);
  void refuse(Refusal reason, const std::string& what);

  zmq::context_t& context_;
  std::shared_ptr<const CurveKeyring> keyring_;
  OnRefused on_refused_;
  std::atomic<bool> stop_{false};
  std::atomic<uint64_t> refused_{0};
  std::atomic<uint64_t> accepted_{0};
  std::mutex mutex_;                      // guards pending_monitors_, next_monitor_
  std::vector<std::string> pending_monitors_;
  int next_monitor_ = 0;
  std::set<std::string> logged_;          // guard thread only
  std::thread thread_;
  std::atomic<bool> ready_{false};
};

}  // namespace hexplore::transport
