#pragma once
// Conversions between the safety library's plain types and the v1 wire messages.

#include "common/safety/fragment.h"
#include "common/safety/resolver.h"
#include "hexplore/v1/motion.pb.h"
#include "hexplore/v1/safety.pb.h"

namespace hexplore::safety {

v1::PathFragment to_proto(const Fragment& fragment);
// `robot_id` comes from the message header (the fragment itself carries no id).
Fragment from_proto(const v1::PathFragment& message, const std::string& robot_id);
// FollowPath for kFollow, Stop (with the reason) for kStop.
v1::MotionCommand to_motion_command(const Decision& decision);

}  // namespace hexplore::safety
