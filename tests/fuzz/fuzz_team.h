#pragma once
// What every payload harness decodes with: the default team's wire context (roster and
// compact codecs, as ServiceContext gives every socket) and the one function a subscriber
// runs on a payload frame before its handler sees a message.
//
// Input layout of a payload harness: byte 0 holds the header's payload flags (only the
// compressed and codec bits count), the rest is the payload frame. So one corpus reaches the
// protobuf form, the compact codec form and both of them zstd-compressed.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/core/team_config.h"
#include "common/transport/envelope.h"
#include "common/transport/payload_wire.h"
#include "common/transport/socket_options.h"
#include "common/transport/type_id.h"

namespace hexplore::fuzz {

// The default team (two species, two robots), parsed once from text so that a harness needs
// no file: decoders see the roster and codecs a real team's sockets have.
const core::TeamConfig& team();
const transport::SocketOptions& team_socket_options();

// Unpacks and parses a payload frame as a subscriber does; false where the subscriber would
// drop the frame (counted there as malformed).
template <typename Message>
bool decode_payload(const uint8_t* data, size_t size, Message& out) {
  if (size == 0) return false;
  const uint8_t flags = data[0] & (transport::kPayloadCompressed | transport::kPayloadCodec);
  const std::string_view frame(reinterpret_cast<const char*>(data + 1), size - 1);
  const transport::SocketOptions& options = team_socket_options();
  std::string scratch;
  std::string_view bytes;
  const uint16_t type = transport::type_id(Message::descriptor()->full_name());
  if (!transport::unpack_payload(frame, flags, type, options, scratch, bytes)) return false;
  return transport::parse_payload(bytes, flags, type, options, out);
}

}  // namespace hexplore::fuzz
