#pragma once
// The wire envelope: multipart [topic][Header][payload] on PUB/SUB and
// [empty][Header][payload] after the routing id on ROUTER/DEALER. Building and checking the
// Header lives here so that every socket applies the same rules.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <google/protobuf/message.h>
#include <zmq.hpp>

#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "hexplore/v1/header.pb.h"

namespace hexplore::transport {

// The schema version this build speaks (hexplore.v1.SCHEMA_VERSION_CURRENT).
uint32_t current_schema_version();

// Full protobuf name of a message type, e.g. "hexplore.v1.ScanFrame".
template <typename M>
const std::string& type_name() {
  return M::descriptor()->full_name();
}

// Header for an outgoing message, stamped with the wall clock now.
v1::Header make_header(const Identity& identity, uint64_t sequence, std::string_view payload_type,
                       int64_t sim_time_ns);

// Serializes a protobuf message into a ZeroMQ frame without an intermediate string.
zmq::message_t to_frame(const google::protobuf::MessageLite& message);

// Parses a Header frame and checks version and size. `expected_type` empty = any type.
// Returns the reason to drop, or nullopt when the frame is acceptable.
std::optional<DropReason> check_envelope(const zmq::message_t& header_frame, const zmq::message_t& payload_frame,
                                         int64_t max_message_bytes, v1::Header& header_out);

}  // namespace hexplore::transport
