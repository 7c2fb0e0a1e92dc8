#pragma once
// team/path on the radio: a robot's near path (paper eta_p) as centimetre steps from its
// position, its speed in cm/s, the stationary flag and whom it yields to as a roster slot;
// about 15 bytes for a two-waypoint fragment (the protobuf PathFragment took about 150). Not
// carried: body_box_m, which receivers rebuild from the position and the sender's species
// (safety::body_box_any_yaw), so it decodes as unset.

#include "common/transport/payload_codec.h"

namespace hexplore::radio {

class FragmentCodec : public transport::PayloadCodec {
 public:
  const std::string& type() const override;
  void encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
              std::string& out) const override;
  bool decode(std::string_view data, const transport::Roster* roster,
              google::protobuf::MessageLite& message) const override;
};

}  // namespace hexplore::radio
