#pragma once
// What one robot tells its teammates about its motion (mirror of hexplore.v1.PathFragment):
// the near part of its approved path, its speed, whether it stands still and whom it waits for.

#include <string>

#include <Eigen/Core>

#include "common/safety/polyline.h"

namespace hexplore::safety {

struct Fragment {
  std::string robot_id;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Path waypoints_m;                // from the robot's position, at most eta_p long
  double speed_mps = 0.0;          // speed it is driving at now (0 when stationary)
  bool stationary = true;          // stopped (yielding, scanning, blocked, idle)
  Eigen::Vector3d box_min_m = Eigen::Vector3d::Zero();  // body bounding box, world frame
  Eigen::Vector3d box_max_m = Eigen::Vector3d::Zero();
  std::string yielding_to;         // robot it waits for, "" when not yielding
  // A fragment advanced by its age (advance_fragment): where the robot was reported, up to
  // position_m. It may still be anywhere on it (stopped since, and that news lost), so the
  // resolver's last line of defence keeps its distance from all of it. Empty when fresh.
  Path trail_m;

  // Horizontal radius of the body as seen by others: half the larger side of the box.
  double body_radius_m() const;
  // position followed by the waypoints (deduplicated), the path teammates check against.
  Path path() const;
  // Horizontal distance from `p` to the body's possible centres: position_m and the trail.
  double distance_to(const Eigen::Vector3d& p) const;
};

// Axis-aligned box that contains a body of the given half extents at any yaw, centred on p.
void body_box_any_yaw(const Eigen::Vector3d& p, const Eigen::Vector3d& half_extents_m, Eigen::Vector3d& box_min,
                      Eigen::Vector3d& box_max);
// Radius of the horizontal circle around a body of these half extents.
double body_radius_of(const Eigen::Vector3d& half_extents_m);

}  // namespace hexplore::safety
