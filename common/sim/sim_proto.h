#pragma once
// Wire messages from the simulator's types: what a simulated robot publishes as its LiDAR
// scan (ScanFrame) and its pose (Pose, MotionState).

#include <Eigen/Geometry>

#include "common/sim/lidar.h"
#include "common/sim/robot_motion.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/scan.pb.h"

namespace hexplore::sim {

void set_pose(v1::Pose* out, const Eigen::Isometry3d& pose);
v1::ScanFrame to_scan_frame(const LidarScan& scan, const Eigen::Isometry3d& body_pose, double max_range_m);
v1::MotionState to_proto(MotionState state);

}  // namespace hexplore::sim
