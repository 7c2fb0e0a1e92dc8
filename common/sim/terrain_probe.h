#pragma once
// Where a robot body can stand, measured on the ground truth: support heights under a 3x3
// grid over its footprint (found by casting down from one step height above the previous
// support, so the nearest floor below wins, not the topmost, and the underside of an overhang
// is never taken for ground), and the species' limits on them: step height per sample point
// between consecutive poses, slope (pitch/roll of the footprint), clearance above the ground
// (rays up) and obstacles in the direction of travel (rays at body height). Turns in place
// are checked as a sweep of small rotations.

#include <array>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/team_config.h"
#include "common/sim/ray_caster.h"

namespace hexplore::sim {

enum class TerrainVerdict { kOk, kNoGround, kStep, kSlope, kClearance, kObstacle };
const char* to_string(TerrainVerdict v);

// Which way the obstacle rays look: the way the body moves (forward, or backward when it
// reverses), or both ends while it turns in place.
enum class Travel { kForward, kBackward, kTurn };

// The body resting on the ground at one planar position and heading.
struct Footprint {
  Eigen::Vector2d xy = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  std::array<double, 9> heights{};  // index (ix + 1) * 3 + (iy + 1), ix: back/centre/front, iy: right/centre/left
  double ground_z = 0.0;            // mean support height
  double pitch = 0.0;               // rad, positive = nose up
  double roll = 0.0;                // rad, positive = left side up
};

class TerrainProbe {
 public:
  TerrainProbe(const RayCaster& caster, const core::SpeciesConfig& species);

  // Height of the first surface below z_ref + max step (plus a little) at (x, y), searching
  // down to z_ref - 1 m; nullopt when none. Anything higher is no support for a body whose
  // point was at z_ref: a step too high, or an overhang the body would be inside of.
  std::optional<double> support_height(const Eigen::Vector2d& xy, double z_ref) const;

  // The footprint at xy/yaw; sample point k searches below z_refs[k]. nullopt when a sample
  // point has no ground.
  std::optional<Footprint> footprint(const Eigen::Vector2d& xy, double yaw, const std::array<double, 9>& z_refs) const;
  std::optional<Footprint> footprint(const Eigen::Vector2d& xy, double yaw, double z_ref) const;

  // Limits for standing at `to`: slope, clearance and obstacles along its heading (`travel`).
  // With `from` (a short move or a small rotation earlier), also the step at every sample
  // point. A sample whose ground has something on it lower than half the body's clearance
  // stands against a step (kStep); higher up, the body does not fit (kClearance).
  TerrainVerdict check(const Footprint& to, const Footprint* from, Travel travel = Travel::kForward) const;

  // Turns the body in place from `from` to heading `yaw` in rotations of a few degrees, each
  // checked like a move (both ends of the body look for obstacles, every sample point for
  // steps), the shorter way round first, else the longer. nullopt when neither way is free;
  // `why` (optional) says what stopped the shorter way.
  std::optional<Footprint> turn(const Footprint& from, double yaw, TerrainVerdict* why = nullptr) const;

  // Body centre pose for a footprint (the body box rests on the ground).
  Eigen::Isometry3d body_pose(const Footprint& f) const;
  // Footprint sample point k in the world plane.
  Eigen::Vector2d sample_point(const Eigen::Vector2d& xy, double yaw, int k) const;

  const core::SpeciesConfig& species() const { return species_; }

 private:
  const RayCaster& caster_;
  core::SpeciesConfig species_;
};

}  // namespace hexplore::sim
