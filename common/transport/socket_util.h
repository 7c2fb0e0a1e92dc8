#pragma once
// Internal helpers shared by the socket wrappers: apply SocketOptions, bind with a resolved
// endpoint. Not part of the public API.

#include <string>
#include <vector>

#include <zmq.hpp>

#include "common/transport/context.h"
#include "common/transport/socket_options.h"

namespace hexplore::transport::detail {

// Sets SNDHWM, RCVHWM, LINGER and MAXMSGSIZE explicitly.
void apply_options(zmq::socket_t& socket, const SocketOptions& options);
// Binds and returns the endpoint actually bound ("tcp://127.0.0.1:*" -> "tcp://127.0.0.1:41234"),
// as a CURVE server when `options.curve` is set and the endpoint is tcp. Throws
// std::runtime_error naming the endpoint and the ZeroMQ error.
std::string bind(zmq::socket_t& socket, const std::string& endpoint, const SocketOptions& options);
// Connects, as a CURVE client of `peer` (the member whose socket it is) when `options.curve` is
// set and the endpoint is tcp; throws std::runtime_error naming the endpoint, or the peer when
// the keyring has no key for it.
void connect(zmq::socket_t& socket, const std::string& endpoint, const SocketOptions& options,
             const std::string& peer);
// A socket that will bind as a CURVE server: has the context's guard watch its handshakes.
// Throws std::logic_error when CURVE is wanted but the context has no guard (without one,
// libzmq would admit any CURVE client).
void guard_server(Context& context, zmq::socket_t& socket, const SocketOptions& options);
// Receives one multipart message without blocking into `frames` (cleared first). False when
// none is waiting or the receive failed; a failure is logged once per `who` ("subscriber", ...).
bool receive_frames(zmq::socket_t& socket, std::vector<zmq::message_t>& frames, const char* who);

}  // namespace hexplore::transport::detail
