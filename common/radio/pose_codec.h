#pragma once
// team/pose on the radio: where a robot is, how it is turned, how fast it goes and in which
// motion state, in 5 to 16 bytes on a site within 80 m (the protobuf RobotPose took about
// 130). Position in centimetres, yaw (and pitch and roll only when the body is tilted) in
// 256ths of a turn, velocity in cm/s (omitted while standing, its vertical part while level).
// Not carried: body_half_extents_m (receivers take the species' from the team file),
// odometry_m and collisions (experiment bookkeeping; the station reads them from the sim's
// status), so they decode as zero.

#include "common/transport/payload_codec.h"

namespace hexplore::radio {

class PoseCodec : public transport::PayloadCodec {
 public:
  const std::string& type() const override;
  void encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
              std::string& out) const override;
  bool decode(std::string_view data, const transport::Roster* roster,
              google::protobuf::MessageLite& message) const override;
};

}  // namespace hexplore::radio
