#pragma once
// Inputs and outputs of one planning round, shared by every planner.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"
#include "common/planning/give_up_ledger.h"
#include "common/planning/reference.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

// Points less than this apart in height are on one level: one storey, or a few steps of one
// flight. A storey is at least 3 m high and a flight rises at most ~0.6 m per horizontal metre,
// so a spot within reach (a metre or two) on the same flight passes and the floor above fails.
// Horizontal distances alone would take a spot upstairs for one beneath it.
constexpr double kSameLevelM = 1.5;
inline bool same_level(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::abs(a.z() - b.z()) < kSameLevelM;
}

struct RobotState {
  std::string id;
  int species = 0;  // team species index
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

struct PlanRequest {
  const highlevel::HighLevelMap* map = nullptr;
  std::vector<RobotState> robots;              // the whole team
  int self = 0;                                // index of the planning robot in `robots`
  std::vector<ReferenceSolution> shared;       // teammates' (and own) previous solutions
  uint64_t round = 0;
  const GiveUpLedger* given_up = nullptr;      // ISE supervoxels the team gave up on: no view for them
};

// One robot's part of the team solution.
struct RobotPlan {
  std::string robot_id;
  std::vector<uint64_t> cluster_ids;
  std::vector<Eigen::Vector3d> cluster_centers;
  double route_length_m = 0.0;  // graph length from the robot through its clusters
  double cost_s = 0.0;          // cost(V_r) of the paper (transition + execution time)
  double private_cost_s = 0.0;  // the part of cost_s spent on clusters only this robot's species may take
  std::vector<TaskView> route;  // exploration route (only filled for the planning robot)
};

struct ExecutablePlan {
  bool valid = false;
  std::vector<Eigen::Vector3d> waypoints;  // topology-graph vertices from the robot to the goal
  std::vector<uint64_t> keys;              // their vertex keys
  TaskView goal;
};

struct StageTimes {
  double views_s = 0.0;
  double clustering_s = 0.0;
  double assignment_s = 0.0;
  double mnss_s = 0.0;
  double total_s = 0.0;
};

struct PlanResult {
  uint64_t round = 0;
  std::string planner;
  std::vector<RobotPlan> robots;  // same order as PlanRequest::robots
  double fitness = 0.0;
  int ga_generations = 0;
  int views = 0;
  int clusters = 0;
  int dropped_clusters = 0;       // clusters no robot can reach or serve
  int open_views = 0;             // views in clusters some robot can serve (0 = nothing left to do)
  std::optional<double> agreement;  // share of clusters assigned as in the reference
  std::string reference_source;     // whose shared solution was the reference ("" = none)
  int path_species = -1;            // whose terrain the planning robot's paths use (-1: its own)
  StageTimes times;
  ViewGenerationStats view_stats;

  // This round as a shareable reference solution.
  ReferenceSolution as_reference(const std::string& source_robot) const;
};

}  // namespace hexplore::planning
