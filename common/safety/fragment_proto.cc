#include "common/safety/fragment_proto.h"

#include "common/radio/vec3_proto.h"

namespace hexplore::safety {

using radio::vec;

v1::PathFragment to_proto(const Fragment& fragment) {
  v1::PathFragment m;
  radio::set(m.mutable_position_m(), fragment.position_m);
  for (const auto& w : fragment.waypoints_m) radio::set(m.add_waypoints_m(), w);
  m.set_speed_mps(fragment.speed_mps);
  m.set_stationary(fragment.stationary);
  radio::set(m.mutable_body_box_m()->mutable_min_m(), fragment.box_min_m);
  radio::set(m.mutable_body_box_m()->mutable_max_m(), fragment.box_max_m);
  m.set_yielding_to(fragment.yielding_to);
  return m;
}

Fragment from_proto(const v1::PathFragment& message, const std::string& robot_id) {
  Fragment f;
  f.robot_id = robot_id;
  f.position_m = vec(message.position_m());
  for (const auto& w : message.waypoints_m()) f.waypoints_m.push_back(vec(w));
  f.speed_mps = message.speed_mps();
  f.stationary = message.stationary();
  f.box_min_m = vec(message.body_box_m().min_m());
  f.box_max_m = vec(message.body_box_m().max_m());
  f.yielding_to = message.yielding_to();
  return f;
}

v1::MotionCommand to_motion_command(const Decision& decision) {
  v1::MotionCommand m;
  if (decision.kind == DecisionKind::kStop) {
    m.mutable_stop()->set_reason(decision.reason);
    return m;
  }
  auto* follow = m.mutable_follow();
  for (const auto& w : decision.waypoints) radio::set(follow->add_waypoints_m(), w);
  follow->set_speed_mps(decision.speed_mps);
  return m;
}

}  // namespace hexplore::safety
