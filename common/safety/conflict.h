#pragma once
// Conflict detection between two robots' near paths: where they come within a safety distance
// of each other, how far along each path that zone begins, and the time each needs to reach it
// (time-to-collision, paper "Collision Avoidance").

#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "common/safety/polyline.h"

namespace hexplore::safety {

enum class ConflictKind { kCrossing, kHeadOn, kFollowing };
std::string_view conflict_kind_name(ConflictKind kind);

struct Conflict {
  ConflictKind kind = ConflictKind::kCrossing;
  double own_entry_m = 0.0;     // arc length along the own path where the zone begins
  double peer_entry_m = 0.0;    // same along the peer's path
  Eigen::Vector3d own_point = Eigen::Vector3d::Zero();   // own path point at its entry
  Eigen::Vector3d peer_point = Eigen::Vector3d::Zero();
};

// The zone is every pair of points (one per path) closer than `safety_distance_m`
// horizontally; entries are the smallest arc lengths of such pairs on each path, so both robots
// compute the same pair of numbers from the same two paths. nullopt when the paths stay apart.
std::optional<Conflict> find_conflict(const Path& own, const Path& peer, double safety_distance_m, double step_m);

// Time to reach `distance_m` at `speed_mps`; infinite for a robot that is not moving.
double time_to_reach(double distance_m, double speed_mps);

}  // namespace hexplore::safety
