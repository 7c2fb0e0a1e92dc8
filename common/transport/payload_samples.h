#pragma once
// Samples of what the radio carries, for training a compression dictionary
// (tools/radio/train_map_dictionary.sh): with HEXPLORE_PAYLOAD_SAMPLES=DIR in the environment,
// every team payload sent in a compact (codec) form is also written, before compression, to
// DIR/<type name>-<pid>-<n>.bin. Off (and free) without it; a diagnostic, not a mission setting.

#include <cstdint>
#include <string_view>

#include <google/protobuf/message_lite.h>

#include "common/transport/socket_options.h"

namespace hexplore::transport {

// Writes the codec form of `message` (type `type_name`, id `type`) when sampling is on and the socket has
// a codec for the type; a file that cannot be written is skipped.
void sample_team_payload(const google::protobuf::MessageLite& message, uint16_t type, std::string_view type_name,
                         const SocketOptions& options);

}  // namespace hexplore::transport
