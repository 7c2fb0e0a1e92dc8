#include "common/transport/envelope.h"

#include <cmath>

#include "common/core/clock.h"
#include "common/core/endpoints.h"
#include "common/transport/byte_codec.h"

namespace hexplore::transport {
namespace {

constexpr int kVersionShift = 5;
// Longest string field a named sender may carry (ids, species and service names are short).
constexpr size_t kMaxNameBytes = 128;
// A header is a few bytes (a named one a few dozen); anything longer is not a header.
constexpr size_t kMaxHeaderBytes = 512;

// Service code on the wire: core::ServiceKind + 1; 0 = not a known service (sender goes named).
uint32_t service_code(std::string_view service) {
  const auto kind = core::service_from_name(service);
  return kind ? static_cast<uint32_t>(*kind) + 1 : 0;
}

}  // namespace

uint32_t current_schema_version() { return static_cast<uint32_t>(v1::SCHEMA_VERSION_CURRENT); }

v1::Header make_header(const Identity& identity, uint64_t sequence, std::string_view payload_type,
                       int64_t sim_time_ns) {
  v1::Header header;
  header.set_robot_id(identity.robot_id);
  header.set_species(identity.species);
  header.set_sequence(sequence);
  header.set_send_time_ns(core::wall_time_ns());
  header.set_sim_time_ns(sim_time_ns);
  header.set_schema_version(current_schema_version());
  header.set_payload_type(std::string(payload_type));
  header.set_service(identity.service);
  return header;
}

void encode_header(const v1::Header& header, const Roster* roster, uint8_t payload_flags, bool wall_time,
                   std::string& out) {
  // Slot 0 (the station) doubles as "none" below; `named` decides which is meant.
  const uint32_t slot = roster != nullptr ? roster->slot(header.robot_id()).value_or(UINT32_MAX) : UINT32_MAX;
  const uint32_t service = service_code(header.service());
  // A roster slot also stands for the species, so a sender whose species differs from the
  // team file's (a test double) goes by name.
  const bool named = slot == UINT32_MAX || service == 0 || roster->member(slot)->species != header.species();
  uint8_t flags = static_cast<uint8_t>(payload_flags & (kPayloadCompressed | kPayloadCodec));
  if (named) flags |= kHeaderNamed;
  if (wall_time) flags |= kHeaderWallTime;
  ByteWriter w(out);
  w.u8(static_cast<uint8_t>((header.schema_version() & 0x7) << kVersionShift | flags));
  w.u16(header.payload_type().empty() ? 0 : type_id(header.payload_type()));
  if (named) {
    w.bytes(header.robot_id());
    w.bytes(header.species());
    w.bytes(header.service());
  } else {
    w.varint(uint64_t{slot} << 3 | service);
  }
  w.varint(header.sequence());
  // Round to the millisecond: sim times of poses and timers are multiples of it anyway.
  w.varint(header.sim_time_ns() > 0 ? static_cast<uint64_t>((header.sim_time_ns() + 500'000) / 1'000'000) : 0);
  if (wall_time) w.varint(header.send_time_ns() > 0 ? static_cast<uint64_t>(header.send_time_ns() / 1000) : 0);
}

zmq::message_t header_frame(const v1::Header& header, const Roster* roster, uint8_t payload_flags, bool wall_time) {
  std::string bytes;
  encode_header(header, roster, payload_flags, wall_time, bytes);
  return zmq::message_t(bytes.data(), bytes.size());
}

std::optional<DropReason> decode_header(const void* data, size_t size, const Roster* roster, DecodedHeader& out) {
  out.header.Clear();
  out.type_id = 0;
  out.payload_flags = 0;
  out.has_wall_time = false;
  if (size == 0 || size > kMaxHeaderBytes) return DropReason::kMalformed;
  ByteReader r(data, size);
  const uint8_t first = r.u8();
  const uint32_t version = first >> kVersionShift;
  out.header.set_schema_version(version);
  if (version != current_schema_version()) return DropReason::kWrongVersion;
  const uint8_t flags = first & kHeaderFlagMask;
  if (flags & kHeaderReserved) return DropReason::kMalformed;
  out.payload_flags = flags & (kPayloadCompressed | kPayloadCodec);
  out.has_wall_time = (flags & kHeaderWallTime) != 0;
  out.type_id = r.u16();
  if (flags & kHeaderNamed) {
    const std::string_view id = r.bytes(kMaxNameBytes);
    const std::string_view species = r.bytes(kMaxNameBytes);
    const std::string_view service = r.bytes(kMaxNameBytes);
    out.header.set_robot_id(std::string(id));
    out.header.set_species(std::string(species));
    out.header.set_service(std::string(service));
  } else {
    const uint64_t sender = r.varint();
    const uint32_t service = static_cast<uint32_t>(sender & 0x7);
    const Roster::Member* member =
        roster != nullptr && (sender >> 3) <= UINT32_MAX ? roster->member(static_cast<uint32_t>(sender >> 3)) : nullptr;
    // A slot means nothing without the same roster; a frame from another team is malformed here.
    if (member == nullptr || service == 0 || service > 6 || r.failed()) return DropReason::kMalformed;
    out.header.set_robot_id(member->id);
    out.header.set_species(member->species);
    out.header.set_service(std::string(core::service_name(static_cast<core::ServiceKind>(service - 1))));
  }
  out.header.set_sequence(r.varint());
  const uint64_t sim_ms = r.varint();
  if (sim_ms > static_cast<uint64_t>(INT64_MAX / 1'000'000)) return DropReason::kMalformed;
  out.header.set_sim_time_ns(static_cast<int64_t>(sim_ms) * 1'000'000);
  if (out.has_wall_time) {
    const uint64_t wall_us = r.varint();
    if (wall_us > static_cast<uint64_t>(INT64_MAX / 1000)) return DropReason::kMalformed;
    out.header.set_send_time_ns(static_cast<int64_t>(wall_us) * 1000);
  }
  if (!r.done()) return DropReason::kMalformed;
  return std::nullopt;
}

std::string_view header_sender_key(const void* data, size_t size) {
  if (size < 3 || size > kMaxHeaderBytes) return {};
  ByteReader r(data, size);
  const uint8_t first = r.u8();
  if ((first >> kVersionShift) != current_schema_version()) return {};
  r.u16();
  const uint8_t* start = r.position();
  if (first & kHeaderNamed) {
    r.bytes(kMaxNameBytes);
    r.bytes(kMaxNameBytes);
    r.bytes(kMaxNameBytes);
  } else {
    r.varint();
  }
  if (r.failed()) return {};
  return std::string_view(reinterpret_cast<const char*>(start), static_cast<size_t>(r.position() - start));
}

zmq::message_t to_frame(const google::protobuf::MessageLite& message) {
  const size_t size = message.ByteSizeLong();
  zmq::message_t frame(size);
  if (size > 0) message.SerializeWithCachedSizesToArray(static_cast<uint8_t*>(frame.data()));
  return frame;
}

std::optional<DropReason> check_envelope(const zmq::message_t& header_frame, const zmq::message_t& payload_frame,
                                         int64_t max_message_bytes, const Roster* roster, DecodedHeader& out) {
  if (static_cast<int64_t>(payload_frame.size()) > max_message_bytes) return DropReason::kOversize;
  return decode_header(header_frame.data(), header_frame.size(), roster, out);
}

}  // namespace hexplore::transport
