#pragma once
// Obstacle avoidance around stationary teammates: each stopped robot is an axis-aligned
// bounding box (inflated by the moving robot's own radius and a margin); a path that enters a
// box is locally re-routed through waypoints placed a clearance outside the box corners, or
// cut short before the box when no way around exists (e.g. the goal lies inside it).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/safety/polyline.h"

namespace hexplore::safety {

// A horizontal axis-aligned box owned by a robot (already inflated for the robot that avoids it).
struct ObstacleBox {
  std::string robot_id;
  Eigen::Vector2d min_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d max_m = Eigen::Vector2d::Zero();

  bool contains(const Eigen::Vector2d& p) const;
  // True when the segment passes through the open interior (touching an edge is allowed).
  bool intersects_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
};

struct DetourOptions {
  double clearance_m = 0.2;       // detour waypoints lie this far outside the box corners
  double sample_step_m = 0.05;    // resolution of the box-entry search along the path
  int max_detours = 8;            // boxes handled one after another along the path
  double start_snap_m = 0.5;      // a detour starting this close to the robot starts at the robot
};

struct DetourResult {
  Path path;                       // the path to drive (detoured and/or cut short)
  bool detoured = false;           // at least one box was bypassed
  bool blocked = false;            // cut short before a box that cannot be bypassed
  std::string blocked_by;          // owner of that box
};

// Re-routes `path` (path[0] = the robot) around `boxes`. A box that already contains the robot
// is shrunk until the robot is just outside it, so the robot may move away or along it but
// never closer. Deterministic: ties between equally short detours go to the first corner found.
DetourResult detour_around(const Path& path, std::vector<ObstacleBox> boxes, const DetourOptions& options);

}  // namespace hexplore::safety
