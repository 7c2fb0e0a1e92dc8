// A teammate's RobotPose (team/pose, dead-reckoned) as the mapping service reads it: the
// teammate's body as an oriented box (the team file's body when the message has none),
// extrapolated to a later scan's time, and the point test that keeps the teammate out of the
// map. Input: flags byte, then the payload.

#include "common/perception/teammate_filter.h"
#include "common/radio/pose_schedule.h"
#include "common/radio/vec3_proto.h"
#include "hexplore/v1/pose.pb.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::RobotPose pose;
  if (!fuzz::decode_payload(data, size, pose)) return 0;
  perception::OrientedBox box;
  box.centre = radio::vec(pose.pose().position_m());
  const v1::Quaternion& q = pose.pose().orientation();
  box.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
  if (box.orientation.norm() < 1e-9) box.orientation = Eigen::Quaterniond::Identity();
  box.half_extents_m = radio::vec(pose.body_half_extents_m());
  if (box.half_extents_m.minCoeff() <= 0.0) box.half_extents_m = fuzz::team().species[1].body_half_extents_m;
  if (!box.centre.allFinite() || !box.half_extents_m.allFinite()) return 0;
  const radio::PoseScheduleOptions schedule;
  box.centre = radio::extrapolate_pose(box.centre, radio::vec(pose.velocity_mps()), 0.5, schedule.max_extrapolation_s);
  const perception::BodyFilter filter({box}, 0.1);
  filter.contains(Eigen::Vector3d(1.0, 2.0, 0.5));
  return 0;
}
