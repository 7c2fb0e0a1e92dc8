#pragma once
// The planning process of one robot: keeps the fused high-level map from its hlmap, its own
// and its teammates' poses, and the teammates' previous solutions; plans a round with the
// active planner when the route times out (eta_t), when its robot finished the route, or when
// a teammate finished its route (went idle); publishes the team solution (team/plan) and its
// exploration route, and hands the route to its RouteFollower (common/planning), whose
// paths and sensor aims go to its safety. The active planner comes from the config and can
// be switched at run time by a MissionCommand. It answers OpenTargetsRequest with why the
// remaining coverage targets are still open (common/planning/open_targets.h).
// Robustness: teammates not heard from for params.liveness.planning_team_s (core/liveness.h;
// --peer-timeout-s overrides it), or trying to move without moving
// for --peer-stuck-s, leave the team of the next round (their clusters go to the others).
// Targets that stay incomplete after being observed are given up (GiveUpLedger), and the
// given-up set travels with the team solution, so every planner agrees on what is left.

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/core/liveness.h"
#include "common/highlevel/high_level_map.h"
#include "common/planning/give_up_ledger.h"
#include "common/planning/give_up_sharing.h"
#include "common/planning/passing_observer.h"
#include "common/planning/planner_registry.h"
#include "common/planning/reference.h"
#include "common/planning/route_follower.h"
#include "common/service/mission_state.h"
#include "common/service/service.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "services/planning/fused_map_order.h"
#include "services/planning/solution_gate.h"

namespace hexplore::planning_service {

class PlanningService : public service::Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kPlanning; }
  // Its options (--trace-dir, --reach-m, --give-up-views, ...) are listed with their defaults
  // in common/service/option_catalogue.cc.
  void setup(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;

  // Switches the active planner; false (and logged) for an unknown name. Public for tests.
  bool switch_planner(const std::string& name);
  const std::string& active_planner() const { return active_name_; }

 private:
  void on_map(const v1::FusedMapUpdate& update);
  void request_snapshot();
  void on_mission(const v1::MissionCommand& command);
  void cycle();
  // Seconds since the last round: sim time when the driver stamps it, else wall time.
  double since_last_plan_s() const;
  void replan(const std::string& reason);
  // One step of the route follower; publishes the path (or the aim) it asks for.
  void follow_route();
  planning::DriveState drive_state() const;
  int64_t now_ns() const;  // sim time when the driver stamps it, else the loop's clock
  v1::OpenTargetsReport open_targets_report() const;
  // Whether this round's team solution goes out with its sequences (planning::RouteSharing).
  bool sequences_worth_sending() const;
  // One JSON line per round into --trace-dir/planning-<robot>.jsonl (per-round traces).
  void write_trace(const std::string& reason, const planning::PlanRequest& req, const planning::PlanResult& res);
  // The vertices our paths keep off besides those the follower was blocked at: those within
  // reach of the body of a teammate gone silent (its services died; the robot still stands
  // where it was last heard, and no safety layer reports it any more).
  std::unordered_set<uint64_t> avoided_vertices() const;
  // The live team (self, and teammates heard from recently); sets `self` to our index in it.
  std::vector<planning::RobotState> team_states(int& self) const;
  // Whether a robot of the last round's team has left it since (gone silent, or stuck).
  bool team_shrank() const;

  service::ServiceContext* context_ = nullptr;
  std::string robot_id_;
  int self_ = 0;
  planning::TeamCapabilities capabilities_;
  planning::PlannerOptions options_;
  planning::PlannerRegistry registry_ = planning::PlannerRegistry::builtin();
  std::map<std::string, std::unique_ptr<planning::Planner>> planners_;
  planning::Planner* active_ = nullptr;
  std::string active_name_;

  std::unique_ptr<highlevel::HighLevelMap> map_;
  FusedMapOrder map_order_;
  std::vector<std::string> planned_team_;  // the robots the last round divided the work among
  bool snapshot_pending_ = false;
  std::map<std::string, Eigen::Vector3d> positions_;  // robot id -> last known position
  std::map<std::string, planning::ReferenceSolution> shared_;  // source robot -> solution
  // Our solution as the teammates hold it: the last one sent with its sequences.
  std::optional<planning::ReferenceSolution> held_by_teammates_;
  bool peer_finished_ = false;                        // a teammate went idle (route done)
  std::map<std::string, int> peer_motion_;            // robot id -> last v1::MotionState
  core::Liveness teammates_{core::LivenessParams{}.planning_team_s};  // heard from by team/pose
  std::map<std::string, Eigen::Vector3d> peer_anchor_;  // robot id -> where it last moved 0.5 m from
  std::map<std::string, int64_t> peer_moved_ns_;      // robot id -> now_ns() when it got there
  planning::GiveUpLedger ledger_;                     // targets given up by us and the team
  planning::GiveUpSharing give_up_sharing_;           // which of them the next team solution carries
  SolutionGate solution_gate_{10.0};                  // whether a round's solution goes out (refresh: eta_t)
  std::map<std::string, uint64_t> shared_rounds_;     // each teammate's latest team-solution round
  std::unique_ptr<planning::RouteFollower> follower_;  // executes our route
  std::unique_ptr<planning::PassingObserver> passing_;  // what we see on the way counts too
  double last_look_s_ = -1.0;
  int species_index_ = 0;
  int own_motion_ = 0;                                // our last v1::MotionState
  int64_t sim_time_ns_ = 0;
  double odometry_m_ = 0.0;                           // distance driven, from our driver
  std::ofstream trace_;                           // per-round traces (--trace-dir)
  std::string trace_dir_;
  double trace_graph_period_s_ = 0.0;             // how often the graph goes into the traces (0: never)
  double graph_traced_s_ = -1e300;                // when it last did
  int64_t last_plan_sim_ns_ = 0;

  service::MissionState mission_;  // the station starts and stops our rounds
  uint64_t round_ = 0;
  size_t last_views_ = 0;             // task views of the latest round (0 = exploration done)
  double last_planning_time_s_ = 0.0;
  int64_t last_plan_ns_ = 0;
  double eta_t_s_ = 10.0;
  double min_replan_s_ = 1.0;
  double speed_mps_ = 0.5;
  double peer_stuck_s_ = 30.0;

  metrics::Histogram* stage_views_ = nullptr;
  metrics::Histogram* stage_clustering_ = nullptr;
  metrics::Histogram* stage_assignment_ = nullptr;
  metrics::Histogram* stage_mnss_ = nullptr;
  metrics::Histogram* stage_total_ = nullptr;
  metrics::Gauge* views_ = nullptr;
  metrics::Gauge* clusters_ = nullptr;
  metrics::Gauge* generations_ = nullptr;
  metrics::Gauge* fitness_ = nullptr;
  metrics::Gauge* agreement_ = nullptr;
  metrics::Counter* malformed_supervoxels_ = nullptr;
  metrics::CounterFamily* rounds_ = nullptr;
  metrics::CounterFamily* switches_ = nullptr;
  metrics::GaugeFamily* active_gauge_ = nullptr;
  metrics::Labels labels_;
};

}  // namespace hexplore::planning_service
