#pragma once
// Where a gimbal points while a robot dwells at a facade view. A long-range LiDAR on a gimbal
// (the MR1000's Livox Horizon: 90 deg x 22.5 deg) sees every target inside its field of view in
// each scan, so the view's targets are grouped into windows that fit in it, and the dwell is
// shared by the windows rather than by the targets one at a time: a view of fifteen targets on
// one facade takes two or three aims of several seconds each instead of fifteen half-second
// ones, which gave each target a single scan (common/planning/README.md, "Aiming at what the
// sensor sees at once").

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace hexplore::planning {

struct AimTarget {
  uint64_t key = 0;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
};

struct AimWindow {
  std::vector<uint64_t> targets;               // in the order they were given
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  // where to point: the middle of the window
};

// Groups `targets` seen from `from` into windows that fit in +-half_yaw_deg by +-half_pitch_deg
// about their aim. Greedy set cover: each window is the placement holding the most targets not
// yet in one (ties: the earlier targets' placement), aimed at the middle of what it holds,
// until every target is in one. Windows come in the order of their first target. A half-width
// of zero (or less) makes one window per target, aimed at it. O(n^3) in the targets (a view
// holds tens).
std::vector<AimWindow> aim_windows(const Eigen::Vector3d& from, const std::vector<AimTarget>& targets,
                                   double half_yaw_deg, double half_pitch_deg);

}  // namespace hexplore::planning
