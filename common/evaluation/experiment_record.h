#pragma once
// What the station's experiment recorder accumulates during one mission: the paper's metrics
// (Simulations section) in plain data, independent of how they were collected.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hexplore::evaluation {

// Reconstruction completeness at one sim time, as fractions in [0, 1].
struct CompletenessSample {
  double sim_time_s = 0.0;
  double team = 0.0;             // union of every robot's occupied voxels
  double team_observable = 0.0;  // restricted to ground truth the team could observe
  std::map<std::string, double> per_robot;
};

// One robot's trajectory and per-robot totals.
struct RobotTrack {
  std::string species;
  std::vector<double> times_s;
  std::vector<Eigen::Vector3d> positions_m;
  std::vector<Eigen::Quaterniond> orientations;  // body orientation at each position (world frame)
  double length_m = 0.0;
  uint32_t collisions = 0;
  std::string last_state;
  // Status counters since the start, "service.value" (evaluation::status_counters()); radio
  // drops per reporting service ("hlmap.radio_lost", ...).
  std::map<std::string, double> counters;
  // Map convergence, from the latest hlmap status: the sequence number of this robot's own
  // latest increment, and how far it has applied each teammate's (-1 / absent: not heard).
  double own_increment_seq = -1.0;
  std::map<std::string, double> synced_seq;
  // Stretches of mission time this robot's hlmap did not hold what a teammate last sent (its
  // status in_sync.<teammate> = 0: a gap, a wanted snapshot, a digest that differed), per
  // teammate, as [from, to] seconds; to < 0 while it lasts.
  std::map<std::string, std::vector<std::pair<double, double>>> unsynced;

  // Sum of the counters named `value` over every service ("radio_lost").
  double counter_sum(const std::string& value) const;
  double counter(const std::string& key) const;
  // Longest stretch of sim time the driver reported BLOCKED without a break (from its poses'
  // motion states), and when the current stretch began (-1: not blocked now).
  double longest_blocked_s = 0.0;
  double blocked_since_s = -1.0;
};

// The communication categories the paper reports; bytes on the matching team topic.
inline const std::vector<std::string>& communication_categories() {
  static const std::vector<std::string> kCategories = {"pose", "incremental_map", "executable_path",
                                                       "exploration_route"};
  return kCategories;
}

// One coverage target (ISE supervoxel) still open at the end, as one robot's planner saw it
// (planning::OpenTarget, in plain data).
struct OpenTargetRow {
  double sim_time_s = 0.0;  // when the robot's planner reported it
  std::string robot;
  uint64_t key = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  bool facade = false;
  int voxels = 0;
  int covered_voxels = 0;
  std::string gap;    // core::CoverageGap name: no_normal, angle, distance, density
  std::string state;  // planning::TargetOutcome name: has_view, given_up, no_viewpoint, ...
  int attempts = 0;
};

struct ExperimentRecord {
  std::string scene;
  std::string planner;
  std::string mode;  // "processes", "composed" or "lockstep"
  uint64_t seed = 0;
  uint64_t planner_seed = 0;  // params.planner_seed (0: the planners drew from `seed`)
  std::vector<CompletenessSample> completeness;
  std::map<std::string, RobotTrack> robots;
  std::map<std::string, std::vector<double>> planning_times_s;  // per robot, one per round
  // robot -> category -> bytes (and messages) sent on the team topic of that category.
  std::map<std::string, std::map<std::string, uint64_t>> team_bytes;
  std::map<std::string, std::map<std::string, uint64_t>> team_messages;
  double exploration_time_s = 0.0;
  std::string end_reason;  // "no task views remain", "time limit", "stopped", ...
  double wall_time_s = 0.0;
  // Times the station was restarted mid-mission and resumed this record, and the mission time
  // it heard nothing meanwhile (no poses, traffic or planning rounds were recorded then).
  uint32_t station_restarts = 0;
  double station_unrecorded_s = 0.0;
  // The team's reconstruction: occupied voxel centres of the union map at the end, on a grid
  // of map_resolution_m (exported as map.ply, map.pcd, map.bt).
  std::vector<Eigen::Vector3f> final_map_points_m;
  double map_resolution_m = 0.15;
  // Why exploration was not finished: each live planner's open targets at the end.
  // Every open-target report of the mission (periodic ones and the final one), in order.
  std::vector<OpenTargetRow> open_targets;
  // The rows of each robot's latest report (what was still open at the end).
  std::vector<OpenTargetRow> latest_open_targets() const;
  // Appends one robot's report taken at `sim_time_s`; a report of that robot at the same time
  // (the final request answered in the tick of a periodic one) is replaced, not doubled.
  void add_open_targets_report(const std::string& robot, double sim_time_s, std::vector<OpenTargetRow> rows);

  // Sum over robots of their final completeness (paper: lower = less overlap... at equal team completeness).
  double accumulated_completeness() const;
  // Increments of `source` that `robot` had not applied by the latest statuses of both (0 when
  // converged; the statuses are taken at slightly different times, so 1 may be in flight).
  // -1 when either was never heard.
  double increments_behind(const std::string& robot, const std::string& source) const;
  double final_team_completeness() const;
};

}  // namespace hexplore::evaluation
