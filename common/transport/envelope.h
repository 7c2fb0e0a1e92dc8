#pragma once
// The wire envelope: multipart [topic][header][payload] on PUB/SUB and [empty][header][payload]
// after the routing id on ROUTER/DEALER. The header frame is the compact v2 envelope below;
// handlers see it decoded into a hexplore.v1.Header. Building and checking it lives here so
// that every socket applies the same rules.
//
// Compact header (since schema version 2), every field needed and nothing repeated that the team
// file already says:
//   byte 0     bits 7..5: schema version; bits 4..0: flags
//                0x01 named     the sender follows as strings (robot id, species, service),
//                               not as a roster slot (tools, tests, robots off the roster)
//                0x02 wall      a wall-clock send time follows (robot-local topics only: it
//                               feeds the latency histograms; the radio carries sim time only)
//                0x04 zstd      the payload is zstd-compressed
//                0x08 codec     the payload is in its type's compact codec form, not protobuf
//                0x10 reserved  must be 0
//   bytes 1-2  payload type id, little-endian (type_id.h); 0 = no payload ("not served")
//   varint     sender: roster slot << 3 | service code (1 sim, 2 mapping, 3 hlmap, 4 planning,
//              5 safety, 6 station), or with `named`: three length-prefixed strings
//   varint     sequence (per publisher socket and topic)
//   varint     sim time the payload refers to, milliseconds (negative times are sent as 0)
//   [varint]   with `wall`: wall send time, microseconds since the Unix epoch
// A pose on the radio thus carries 7-9 header bytes where the protobuf Header took about 70.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <google/protobuf/message.h>
#include <zmq.hpp>

#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "common/transport/roster.h"
#include "common/transport/type_id.h"
#include "hexplore/v1/header.pb.h"

namespace hexplore::transport {

// The schema version this build speaks (hexplore.v1.SCHEMA_VERSION_CURRENT).
uint32_t current_schema_version();

// Header flags (byte 0, bits 4..0).
inline constexpr uint8_t kHeaderNamed = 0x01;
inline constexpr uint8_t kHeaderWallTime = 0x02;
inline constexpr uint8_t kPayloadCompressed = 0x04;
inline constexpr uint8_t kPayloadCodec = 0x08;
inline constexpr uint8_t kHeaderFlagMask = 0x1f;
inline constexpr uint8_t kHeaderReserved = 0x10;

// Full protobuf name of a message type, e.g. "hexplore.v1.ScanFrame".
template <typename M>
const std::string& type_name() {
  return M::descriptor()->full_name();
}

// Header for an outgoing message (wall send time now, schema version, payload type name).
v1::Header make_header(const Identity& identity, uint64_t sequence, std::string_view payload_type,
                       int64_t sim_time_ns);

// Encodes `header` compactly: the type id of header.payload_type() ("" = none), the version
// from header.schema_version(), the sender as a slot of `roster` when it is on it (else by
// name), and `payload_flags` (kPayloadCompressed, kPayloadCodec). `wall_time` adds the wall
// send time. Appends to `out`. Sockets pass the roster for radio traffic only (team topics,
// replies to a teammate), so that robot-local traffic stays readable without one.
void encode_header(const v1::Header& header, const Roster* roster, uint8_t payload_flags, bool wall_time,
                   std::string& out);
zmq::message_t header_frame(const v1::Header& header, const Roster* roster, uint8_t payload_flags = 0,
                            bool wall_time = true);

// A decoded header frame: the header fields (payload_type left empty: the receiver fills in
// the name of the handler type that matched `type_id`), the type id and the payload flags.
struct DecodedHeader {
  v1::Header header;
  uint16_t type_id = 0;
  uint8_t payload_flags = 0;
  bool has_wall_time = false;
};

// Decodes a header frame; returns the reason to drop (kWrongVersion, kMalformed), or nullopt.
std::optional<DropReason> decode_header(const void* data, size_t size, const Roster* roster, DecodedHeader& out);

// The bytes of a header frame that name its sender (roster slot or strings), "" when the
// frame is no v2 header: lockstep orders one step's messages by it without a roster.
std::string_view header_sender_key(const void* data, size_t size);

// Serializes a protobuf message into a ZeroMQ frame without an intermediate string.
zmq::message_t to_frame(const google::protobuf::MessageLite& message);

// Checks the payload size against `max_message_bytes` and decodes the header frame.
// Returns the reason to drop, or nullopt when the frame is acceptable.
std::optional<DropReason> check_envelope(const zmq::message_t& header_frame, const zmq::message_t& payload_frame,
                                         int64_t max_message_bytes, const Roster* roster, DecodedHeader& out);

}  // namespace hexplore::transport
