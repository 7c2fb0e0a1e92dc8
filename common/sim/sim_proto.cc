#include "common/sim/sim_proto.h"

#include "common/radio/vec3_proto.h"

namespace hexplore::sim {

void set_pose(v1::Pose* out, const Eigen::Isometry3d& pose) {
  radio::set(out->mutable_position_m(), pose.translation());
  const Eigen::Quaterniond q(pose.linear());
  out->mutable_orientation()->set_w(q.w());
  out->mutable_orientation()->set_x(q.x());
  out->mutable_orientation()->set_y(q.y());
  out->mutable_orientation()->set_z(q.z());
}

v1::MotionState to_proto(MotionState state) {
  switch (state) {
    case MotionState::kIdle: return v1::MOTION_STATE_IDLE;
    case MotionState::kMoving: return v1::MOTION_STATE_MOVING;
    case MotionState::kStopped: return v1::MOTION_STATE_STOPPED;
    case MotionState::kBlocked: return v1::MOTION_STATE_BLOCKED;
    case MotionState::kEmergencyStop: return v1::MOTION_STATE_EMERGENCY_STOP;
  }
  return v1::MOTION_STATE_UNSPECIFIED;
}

v1::ScanFrame to_scan_frame(const LidarScan& scan, const Eigen::Isometry3d& body_pose, double max_range_m) {
  v1::ScanFrame frame;
  frame.set_sensor_name(scan.sensor_name);
  radio::set(frame.mutable_sensor_origin_m(), scan.origin);
  set_pose(frame.mutable_body_pose(), body_pose);
  // Eigen::Vector3f is three packed floats; the wire format is little-endian float32 (x86/ARM).
  static_assert(sizeof(Eigen::Vector3f) == 12);
  frame.mutable_points_xyz_f32()->assign(reinterpret_cast<const char*>(scan.points.data()), scan.points.size() * 12);
  frame.set_point_count(static_cast<uint32_t>(scan.points.size()));
  frame.set_max_range_m(max_range_m);
  return frame;
}

}  // namespace hexplore::sim
