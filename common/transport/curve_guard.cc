#include "common/transport/curve_guard.h"

#include <cstring>

#include <zmq.h>
#include <zmq_addon.hpp>

#include "common/core/log.h"

namespace hexplore::transport {

namespace {

constexpr const char* kZapEndpoint = "inproc://zeromq.zap.01";
constexpr int kPollMs = 50;  // how soon the thread notices a stop or a new socket to watch

std::string z85_of(const uint8_t* key32) {
  char text[41];
  zmq_z85_encode(text, key32, 32);
  return text;
}

}  // namespace

CurveGuard::CurveGuard(zmq::context_t& context, std::shared_ptr<const CurveKeyring> keyring, OnRefused on_refused)
    : context_(context), keyring_(std::move(keyring)), on_refused_(std::move(on_refused)) {
  // Bound here, before any server socket exists, so that no handshake finds no handler (with
  // none, libzmq lets every CURVE client in); the thread takes the socket over.
  auto zap = std::make_shared<zmq::socket_t>(context_, zmq::socket_type::rep);
  zap->set(zmq::sockopt::linger, 0);
  zap->bind(kZapEndpoint);
  thread_ = std::thread([this, zap] {
    zmq::socket_t socket = std::move(*zap);
    std::vector<zmq::socket_t> monitors;
    while (!stop_.load()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& endpoint : pending_monitors_) {
          monitors.emplace_back(context_, zmq::socket_type::pair);
          monitors.back().set(zmq::sockopt::linger, 0);
          monitors.back().connect(endpoint);
        }
        pending_monitors_.clear();
      }
      std::vector<zmq::pollitem_t> items{{socket.handle(), 0, ZMQ_POLLIN, 0}};
      for (auto& m : monitors) items.push_back({m.handle(), 0, ZMQ_POLLIN, 0});
      try {
        zmq::poll(items.data(), items.size(), std::chrono::milliseconds(kPollMs));
      } catch (const zmq::error_t& e) {
        if (e.num() == ETERM) break;
        continue;
      }
      if (items[0].revents & ZMQ_POLLIN) answer(socket);
      for (size_t i = 1; i < items.size(); ++i) {
        if (!(items[i].revents & ZMQ_POLLIN)) continue;
        std::vector<zmq::message_t> event;
        if (!zmq::recv_multipart(monitors[i - 1], std::back_inserter(event), zmq::recv_flags::dontwait)) continue;
        if (event.empty() || event[0].size() < 6) continue;
        uint16_t id = 0;
        std::memcpy(&id, event[0].data(), sizeof id);
        // A failed authentication (ZAP said no) is counted by answer(); these fail before it.
        if (id == ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL || id == ZMQ_EVENT_HANDSHAKE_FAILED_NO_DETAIL)
          refuse(Refusal::kHandshake, event.size() > 1 ? event[1].to_string() : "");
      }
    }
  });
}

CurveGuard::~CurveGuard() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void CurveGuard::watch(zmq::socket_t& socket) {
  std::string endpoint;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    endpoint = "inproc://hexplore-curve-monitor-" + std::to_string(reinterpret_cast<uintptr_t>(this)) + "-" +
               std::to_string(next_monitor_++);
  }
  if (zmq_socket_monitor(socket.handle(), endpoint.c_str(),
                         ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL | ZMQ_EVENT_HANDSHAKE_FAILED_NO_DETAIL) != 0)
    throw std::runtime_error(std::string("curve: cannot watch a socket: ") + zmq_strerror(zmq_errno()));
  std::lock_guard<std::mutex> lock(mutex_);
  pending_monitors_.push_back(endpoint);
}

void CurveGuard::answer(zmq::socket_t& zap) {
  std::vector<zmq::message_t> request;
  if (!zmq::recv_multipart(zap, std::back_inserter(request), zmq::recv_flags::dontwait)) return;
  // version, request id, domain, address, routing id, mechanism, credentials...
  const bool well_formed = request.size() >= 6 && request[0].to_string() == "1.0";
  std::string status = "400", text = "unknown key", user;
  if (well_formed && request[5].to_string() == "CURVE" && request.size() >= 7 && request[6].size() == 32) {
    const auto* key = static_cast<const uint8_t*>(request[6].data());
    if (const auto member = keyring_->member_of(key)) {
      status = "200";
      text = "OK";
      user = *member;
      ++accepted_;
    } else {
      refuse(Refusal::kUnknownKey, z85_of(key) + " from " + request[3].to_string());
    }
  } else {
    text = "CURVE required";
    refuse(Refusal::kHandshake, well_formed ? request[5].to_string() + " from " + request[3].to_string() : "bad ZAP request");
  }
  std::vector<zmq::message_t> reply;
  reply.emplace_back(std::string("1.0"));
  reply.emplace_back(request.size() > 1 ? request[1].to_string() : std::string());
  reply.emplace_back(status);
  reply.emplace_back(text);
  reply.emplace_back(user);
  reply.emplace_back();  // no metadata
  zmq::send_multipart(zap, reply, zmq::send_flags::dontwait);
}

void CurveGuard::refuse(Refusal reason, const std::string& what) {
  ++refused_;
  // Once per key (or failure kind and address): a rogue retrying every 100 ms must not flood the log.
  const std::string key = what.substr(0, what.find(" from "));
  if (logged_.insert(key).second)
    core::LogLine(core::LogLevel::kWarn, "transport")
        << (reason == Refusal::kUnknownKey ? "refused a peer with an unknown CURVE key " : "refused a peer: handshake failed ")
        << what << " (logged once per key)";
  if (on_refused_) on_refused_(reason, what);
}

}  // namespace hexplore::transport
