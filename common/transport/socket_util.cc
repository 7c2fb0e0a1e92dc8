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

std::string bind(zmq::socket_t& socket, const std::string& endpoint) {
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

void connect(zmq::socket_t& socket, const std::string& endpoint) {
  try {
    socket.connect(endpoint);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("transport: cannot connect to " + endpoint + ": " + e.what());
  }
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
