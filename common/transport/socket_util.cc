#include "common/transport/socket_util.h"

#include <filesystem>
#include <limits>
#include <system_error>
#include <stdexcept>

#include <zmq_addon.hpp>

#include "common/core/log.h"

namespace hexplore::transport::detail {

void apply_options(zmq::socket_t& socket, const SocketOptions& options) {
  socket.set(zmq::sockopt::sndhwm, options.send_high_water_mark);
  socket.set(zmq::sockopt::rcvhwm, options.receive_high_water_mark);
  socket.set(zmq::sockopt::linger, options.linger_ms);
  constexpr int64_t kSlack = 64 * 1024;
  const int64_t limit = options.max_message_bytes > (std::numeric_limits<int64_t>::max() - kSlack) / 2
                            ? -1
                            : options.max_message_bytes * 2 + kSlack;
  socket.set(zmq::sockopt::maxmsgsize, limit);
}

namespace {

bool is_tcp(const std::string& endpoint) { return endpoint.rfind("tcp://", 0) == 0; }

// Options are read when a bind or connect creates its listener or session, so each endpoint
// gets the mechanism that fits it (a publisher may bind tcp beside inproc).
void set_mechanism(zmq::socket_t& socket, const std::string& endpoint, const SocketOptions& options, bool server,
                   const std::string& peer) {
  if (!options.curve || !is_tcp(endpoint)) {
    if (options.curve) socket.set(zmq::sockopt::curve_server, 0);  // back to NULL after a tcp endpoint
    return;
  }
  const CurveCredentials& c = *options.curve;
  socket.set(zmq::sockopt::zap_domain, "hexplore");
  if (server) {
    socket.set(zmq::sockopt::curve_server, 1);
    socket.set(zmq::sockopt::curve_secretkey, c.own.secret_key);
    return;
  }
  std::string server_key;
  try {
    server_key = c.keyring->public_key(peer);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("transport: cannot connect to " + endpoint + " with CURVE: " + e.what());
  }
  socket.set(zmq::sockopt::curve_serverkey, server_key);
  socket.set(zmq::sockopt::curve_publickey, c.own.public_key);
  socket.set(zmq::sockopt::curve_secretkey, c.own.secret_key);
}

}  // namespace

std::string bind(zmq::socket_t& socket, const std::string& endpoint, const SocketOptions& options) {
  set_mechanism(socket, endpoint, options, /*server=*/true, "");
  // ipc endpoints are files: their folder (TransportConfig::ipc_dir) must exist before bind.
  constexpr std::string_view kIpc = "ipc://";
  if (endpoint.rfind(kIpc, 0) == 0) {
    const std::filesystem::path folder = std::filesystem::path(endpoint.substr(kIpc.size())).parent_path();
    std::error_code error;
    if (!folder.empty()) std::filesystem::create_directories(folder, error);
    if (error) throw std::runtime_error("transport: cannot create " + folder.string() + " for " + endpoint + ": " + error.message());
  }
  try {
    socket.bind(endpoint);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("transport: cannot bind " + endpoint + ": " + e.what());
  }
  return socket.get(zmq::sockopt::last_endpoint);
}

void connect(zmq::socket_t& socket, const std::string& endpoint, const SocketOptions& options,
             const std::string& peer) {
  set_mechanism(socket, endpoint, options, /*server=*/false, peer);
  try {
    socket.connect(endpoint);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("transport: cannot connect to " + endpoint + ": " + e.what());
  }
}

void guard_server(Context& context, zmq::socket_t& socket, const SocketOptions& options) {
  if (!options.curve) return;
  if (context.curve_guard() == nullptr)
    throw std::logic_error("transport: CURVE keys without a guard (call Context::enable_curve first)");
  context.curve_guard()->watch(socket);
}

bool receive_frames(zmq::socket_t& socket, std::vector<zmq::message_t>& frames, const char* who) {
  frames.clear();
  try {
    return zmq::recv_multipart(socket, std::back_inserter(frames), zmq::recv_flags::dontwait).has_value();
  } catch (const zmq::error_t& e) {
    core::log_once(core::LogLevel::kError, "transport", std::string(who) + "-recv",
                   std::string("receive failed: ") + e.what());
    return false;
  }
}

}  // namespace hexplore::transport::detail
