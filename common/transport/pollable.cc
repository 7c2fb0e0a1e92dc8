#include "common/transport/pollable.h"

#include "common/transport/socket_util.h"

namespace hexplore::transport {

size_t Pollable::drain(size_t max) {
  zmq::socket_t* socket = input_socket();
  if (socket == nullptr) return 0;
  std::vector<zmq::message_t> frames;
  size_t taken = 0;
  while (taken < max && detail::receive_frames(*socket, frames, role())) {
    ++taken;
    handle(frames);
  }
  return taken;
}

}  // namespace hexplore::transport
