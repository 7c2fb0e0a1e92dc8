#pragma once
// A message's payload frame: protobuf, or on team topics its compact codec form (when the
// socket has one for the type), zstd-compressed when that makes it smaller. The header's
// payload flags say which; decode_payload undoes exactly what they say.

#include <cstdint>
#include <string>
#include <string_view>

#include <google/protobuf/message_lite.h>

#include "common/transport/socket_options.h"

namespace hexplore::transport {

// Fills `out` with the payload of `message` (type id `type`) and returns its payload flags.
uint8_t encode_payload(const google::protobuf::MessageLite& message, uint16_t type, bool team_topic,
                       const SocketOptions& options, std::string& out);

// The payload bytes to parse: `data` itself, or its decompressed form in `scratch` (with the
// dictionary of type `type`'s codec where the frame names one). False when compressed data is
// corrupt, would exceed max_message_bytes, or names a dictionary this socket does not hold.
bool unpack_payload(std::string_view data, uint8_t flags, uint16_t type, const SocketOptions& options,
                    std::string& scratch, std::string_view& out);

// Parses unpacked payload bytes into `message` (type id `type`): the codec's form when
// `flags` has kPayloadCodec, else protobuf. False when they do not parse.
bool parse_payload(std::string_view bytes, uint8_t flags, uint16_t type, const SocketOptions& options,
                   google::protobuf::MessageLite& message);

}  // namespace hexplore::transport
