#pragma once
// Polyline helpers for robot paths (world frame, metres). Ground robots: distances that decide
// conflicts and obstacles are horizontal (xy); z is carried along for the driver.

#include <vector>

#include <Eigen/Core>

namespace hexplore::safety {

using Path = std::vector<Eigen::Vector3d>;

// Horizontal distance between two points.
double distance_xy(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// Sum of horizontal segment lengths.
double path_length(const Path& path);

// The part of `waypoints` still ahead of a robot at `position`: the robot position followed by
// the path from the closest point on it (the earliest one on ties). Empty input -> {position}.
Path remaining_path(const Eigen::Vector3d& position, const Path& waypoints);

// Same, looking for the closest point only between arc lengths `from_s` and `to_s` (a robot
// tracking its progress must not jump to a later part of a path that passes nearby, e.g. on
// the other side of a wall). `at_s` receives the arc length of the point chosen.
Path remaining_path(const Eigen::Vector3d& position, const Path& waypoints, double from_s, double to_s, double* at_s);

// The first `max_length_m` of the path (by horizontal length), ending on an interpolated point.
Path truncate_to_length(const Path& path, double max_length_m);

// The point at arc length `s_m` (clamped to the path).
Eigen::Vector3d point_at(const Path& path, double s_m);

// Unit horizontal direction of the path at arc length s (zero for a degenerate path).
Eigen::Vector3d direction_at(const Path& path, double s_m);

// Points every `step_m` along the path including both ends, with their arc lengths.
struct PathSample {
  Eigen::Vector3d point;
  double s_m = 0.0;
};
std::vector<PathSample> sample_path(const Path& path, double step_m);

// Continues the last segment straight on by `extra_m` (path unchanged when degenerate).
Path extend_path(const Path& path, double extra_m);

}  // namespace hexplore::safety
