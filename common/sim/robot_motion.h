#pragma once
// One simulated robot body: follows a commanded waypoint path at its species' speed with
// its pose projected onto the ground truth, turning in place towards each waypoint or, where
// its body cannot turn, reversing to it, or first backing up the way it came (its last poses)
// until it can turn; where a move or turn is still refused, it manoeuvres to the waypoint as a
// local planner would (local_maneuver.h), and stops with BLOCKED only when that finds no way
// either, or the terrain in the way exceeds the species' limits; counts contacts with
// teammates' bodies. Advanced by
// step(dt) only, so a lockstep driver reproduces a run exactly.

#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/team_config.h"
#include "common/sim/proxy_box.h"
#include "common/sim/terrain_probe.h"

namespace hexplore::sim {

enum class MotionState { kIdle, kMoving, kStopped, kBlocked, kEmergencyStop };
const char* to_string(MotionState s);

class RobotMotion {
 public:
  // Places the body at `start` (x, y; z selects the floor: the nearest support below
  // z + clearance) facing yaw. Throws SceneError when there is no ground there or the
  // species cannot stand there.
  RobotMotion(const RayCaster& caster, const core::SpeciesConfig& species, const Eigen::Vector3d& start,
              double yaw_rad, uint32_t id = 0);

  // Follow the waypoints (their x, y; the terrain sets z) at min(speed, species speed);
  // speed <= 0 means the species speed. Ignored during an emergency stop. A waypoint the
  // body cannot turn to face is driven to in reverse (e.g. backing out of a dead end).
  void follow(std::vector<Eigen::Vector3d> waypoints, double speed_mps = 0.0);
  void stop();            // halt, keep nothing of the path
  void emergency_stop();  // halt; follow() is ignored until release()
  void release();         // end an emergency stop

  // Advances the body by dt seconds of sim time; teammates are checked for contact.
  void step(double dt_s, std::span<const ProxyBox> teammates = {});

  MotionState state() const { return state_; }
  TerrainVerdict block_reason() const { return block_reason_; }
  Eigen::Isometry3d body_pose() const { return probe_.body_pose(footprint_); }
  const Footprint& footprint() const { return footprint_; }
  Eigen::Vector3d ground_position() const;
  Eigen::Vector3d velocity() const { return velocity_; }
  double odometry_m() const { return odometry_m_; }
  uint32_t collisions() const { return collisions_; }
  uint32_t maneuvers() const { return maneuvers_; }  // manoeuvres started so far
  size_t waypoints_left() const { return path_.size() - next_; }
  bool reversing() const { return reversing_; }
  ProxyBox body_box() const;
  const core::SpeciesConfig& species() const { return probe_.species(); }

 private:
  void block(TerrainVerdict why);
  void pass_by_near_waypoints();  // leading waypoints closer than a pass-by distance
  void next_waypoint();
  // A move or turn was refused: plan a manoeuvre to the waypoint (local_maneuver.h), once
  // per waypoint. True when one was found and is now under way.
  bool start_maneuver(std::span<const ProxyBox> teammates);
  // Drives the manoeuvre's next pose within `budget` metres; returns the metres used.
  double drive_maneuver(double budget, std::span<const ProxyBox> teammates);
  void remember(const Footprint& f);

  TerrainProbe probe_;
  uint32_t id_;
  Footprint footprint_;
  MotionState state_ = MotionState::kIdle;
  TerrainVerdict block_reason_ = TerrainVerdict::kOk;
  std::vector<Eigen::Vector3d> path_;
  size_t next_ = 0;
  bool reversing_ = false;  // driving backwards to path_[next_]
  std::deque<Footprint> maneuver_;                // poses still to drive, each a move or a turn
  std::optional<Eigen::Vector2d> maneuver_goal_;  // the waypoint a manoeuvre was last searched for
  uint32_t maneuvers_ = 0;
  std::deque<Footprint> trail_;  // poses before the latest moves and turns, newest last
  double speed_mps_ = 0.0;
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  double odometry_m_ = 0.0;
  uint32_t collisions_ = 0;
  std::set<uint32_t> touching_;
};

// Sim time with a real-time factor: step() advances it; wall_period() says how long a
// real-time driver should wait for a sim step (rtf <= 0: as fast as possible).
class SimClock {
 public:
  explicit SimClock(double real_time_factor = 1.0) : rtf_(real_time_factor) {}
  void step(int64_t dt_ns) { now_ns_ += dt_ns; }
  int64_t now_ns() const { return now_ns_; }
  double real_time_factor() const { return rtf_; }
  int64_t wall_period_ns(int64_t sim_dt_ns) const {
    return rtf_ > 0 ? static_cast<int64_t>(static_cast<double>(sim_dt_ns) / rtf_) : 0;
  }

 private:
  double rtf_;
  int64_t now_ns_ = 0;
};

// Length of a polyline (trajectory length per robot).
double trajectory_length(std::span<const Eigen::Vector3d> points);

}  // namespace hexplore::sim
