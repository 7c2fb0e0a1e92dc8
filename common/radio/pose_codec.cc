#include "common/radio/pose_codec.h"
#include "common/radio/vec3_proto.h"

#include <Eigen/Geometry>

#include "common/radio/wire_units.h"
#include "hexplore/v1/pose.pb.h"

namespace hexplore::radio {
namespace {

constexpr uint8_t kStateMask = 0x07;
constexpr uint8_t kTilted = 0x08;
constexpr uint8_t kMoving = 0x10;
constexpr uint8_t kClimbing = 0x20;  // a vertical speed follows (ground robots mostly have none)

}  // namespace

const std::string& PoseCodec::type() const { return v1::RobotPose::descriptor()->full_name(); }

void PoseCodec::encode(const google::protobuf::MessageLite& message, const transport::Roster*,
                       std::string& out) const {
  const auto& pose = static_cast<const v1::RobotPose&>(message);
  const auto& q = pose.pose().orientation();
  Eigen::Quaterniond orientation(q.w(), q.x(), q.y(), q.z());
  orientation = orientation.norm() > 1e-9 ? orientation.normalized() : Eigen::Quaterniond::Identity();
  // Z-Y-X (yaw, pitch, roll) angles of the body.
  const Eigen::Matrix3d m = orientation.toRotationMatrix();
  const double yaw = std::atan2(m(1, 0), m(0, 0));
  const double pitch = std::asin(std::clamp(-m(2, 0), -1.0, 1.0));
  const double roll = std::atan2(m(2, 1), m(2, 2));
  const uint8_t pitch_b = angle_byte(pitch), roll_b = angle_byte(roll);
  const Eigen::Vector3d velocity = vec(pose.velocity_mps());
  const bool climbing = to_cm(velocity.z()) != 0;
  const bool moving = to_cm(velocity.x()) != 0 || to_cm(velocity.y()) != 0 || climbing;
  const bool tilted = pitch_b != 0 || roll_b != 0;
  uint8_t flags = static_cast<uint8_t>(std::clamp<int>(pose.state(), 0, kStateMask));
  if (tilted) flags |= kTilted;
  if (moving) flags |= kMoving;
  if (climbing) flags |= kClimbing;
  transport::ByteWriter w(out);
  w.u8(flags);
  write_cm(w, vec(pose.pose().position_m()), Eigen::Vector3d::Zero());
  w.u8(angle_byte(yaw));
  if (tilted) {
    w.u8(pitch_b);
    w.u8(roll_b);
  }
  if (moving) {
    w.svarint(to_cm(velocity.x()));
    w.svarint(to_cm(velocity.y()));
    if (climbing) w.svarint(to_cm(velocity.z()));
  }
}

bool PoseCodec::decode(std::string_view data, const transport::Roster*, google::protobuf::MessageLite& message) const {
  auto& pose = static_cast<v1::RobotPose&>(message);
  transport::ByteReader r(data);
  const uint8_t flags = r.u8();
  if (flags & ~(kStateMask | kTilted | kMoving | kClimbing)) return false;
  if ((flags & kClimbing) && !(flags & kMoving)) return false;
  const int state = flags & kStateMask;
  if (!v1::MotionState_IsValid(state)) return false;
  const Eigen::Vector3d position = read_cm(r, Eigen::Vector3d::Zero());
  const double yaw = angle_from_byte(r.u8());
  double pitch = 0.0, roll = 0.0;
  if (flags & kTilted) {
    pitch = angle_from_byte(r.u8());
    roll = angle_from_byte(r.u8());
  }
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  if (flags & kMoving) {
    velocity.x() = from_cm(r.svarint());
    velocity.y() = from_cm(r.svarint());
    if (flags & kClimbing) velocity.z() = from_cm(r.svarint());
  }
  if (!r.done()) return false;
  const Eigen::Quaterniond q = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  set(pose.mutable_pose()->mutable_position_m(), position);
  auto* o = pose.mutable_pose()->mutable_orientation();
  o->set_w(q.w());
  o->set_x(q.x());
  o->set_y(q.y());
  o->set_z(q.z());
  set(pose.mutable_velocity_mps(), velocity);
  pose.set_state(static_cast<v1::MotionState>(state));
  return true;
}

}  // namespace hexplore::radio
