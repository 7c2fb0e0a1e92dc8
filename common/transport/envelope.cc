#include "common/transport/envelope.h"

#include "common/core/clock.h"

namespace hexplore::transport {

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

zmq::message_t to_frame(const google::protobuf::MessageLite& message) {
  const size_t size = message.ByteSizeLong();
  zmq::message_t frame(size);
  if (size > 0) message.SerializeWithCachedSizesToArray(static_cast<uint8_t*>(frame.data()));
  return frame;
}

std::optional<DropReason> check_envelope(const zmq::message_t& header_frame, const zmq::message_t& payload_frame,
                                         int64_t max_message_bytes, v1::Header& header_out) {
  if (static_cast<int64_t>(payload_frame.size()) > max_message_bytes) return DropReason::kOversize;
  // A header is a few dozen bytes; anything huge is not a header.
  if (header_frame.size() > 4096) return DropReason::kMalformed;
  header_out.Clear();
  if (!header_out.ParseFromArray(header_frame.data(), static_cast<int>(header_frame.size())))
    return DropReason::kMalformed;
  if (header_out.schema_version() != current_schema_version()) return DropReason::kWrongVersion;
  if (header_out.payload_type().empty()) return DropReason::kMalformed;
  return std::nullopt;
}

}  // namespace hexplore::transport
