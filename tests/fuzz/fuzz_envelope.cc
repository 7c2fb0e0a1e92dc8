// The first two frames of every message a socket receives: the topic frame (a one-byte code
// for team topics) and the header frame, decoded with the team's roster as on team topics.
// Input: byte 0 = length of the topic frame (at most 255), then the topic frame, then the
// header frame.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/transport/envelope.h"
#include "common/transport/topics.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  if (size == 0) return 0;
  const size_t topic_size = std::min<size_t>(data[0], size - 1);
  const std::string_view topic_frame(reinterpret_cast<const char*>(data + 1), topic_size);
  const uint8_t* header = data + 1 + topic_size;
  const size_t header_size = size - 1 - topic_size;

  if (const auto topic = transport::topics::topic_from_wire(topic_frame)) {
    transport::topics::is_valid_topic(*topic);
    transport::topics::topic_label(*topic);
  }
  transport::header_sender_key(header, header_size);
  transport::DecodedHeader out;
  if (!transport::decode_header(header, header_size, fuzz::team_socket_options().roster.get(), out)) {
    // Accepted: what handlers and metrics read of it must be usable.
    transport::topics::peer_label(out.header.robot_id());
    (void)out.header.sim_time_ns();
  }
  transport::decode_header(header, header_size, nullptr, out);  // robot-local traffic: no roster
  return 0;
}
