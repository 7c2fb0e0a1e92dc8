#pragma once
// Executes one robot's exploration route the way the cost model assumes (paper eq.
// 4-xx-delta charges 1 / observation speed per facade task view, and a task view is one
// target): drive to the next view along its executable path, stop there and observe its open
// facade targets for the species' observation time, once per view or once per target
// (FollowerOptions::Dwell; the gimbal of a long-range LiDAR aims at them one after the other,
// moving on early when the target aimed at is complete), then move on. A ground view is done
// on arrival ("observed once a robot reaches its centre"). Views whose targets are all
// complete (or given up) by the time the robot gets there are passed by, and a dwell ends as
// soon as its targets are complete. Whether the targets got complete is judged a settle time
// later, when the map has caught up with the scans, and what stayed incomplete counts as an
// attempt in the team's GiveUpLedger.
// When the robot is blocked or makes no progress within a metre of a facade view's spot, it
// observes the view from where it stands. Otherwise the view is skipped (an attempt too), the
// vertex it could not reach is kept off by later paths, and the robot first backs off along
// its recent trail (a leg of its own, to a trail point at least 1 m back) before the path to
// the next view is planned from there. No sockets: the planning service feeds it poses and the
// map and publishes what it returns.

#include <cstdint>
#include <optional>
#include <span>
#include <unordered_set>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/highlevel/high_level_map.h"
#include "common/planning/give_up_ledger.h"
#include "common/planning/planning_types.h"

namespace hexplore::planning {

struct FollowerOptions {
  double reach_m = 1.0;             // a ground view counts as reached within this horizontal distance
  // A facade view (and a view at the frontier) is observed only from within this distance of its spot: what the view was
  // chosen for (incidence, range, line of sight) holds there, not 1 m short of it (e2e scene,
  // seed 1: the SLUGCAT "observed" a view inside the room from its doorway, three times).
  double observe_reach_m = 0.3;
  double blocked_s = 2.0;           // blocked by terrain this long: skip the view
  double stuck_s = 8.0;             // no 0.5 m of progress this long: skip the view
  // 1 / vartheta_varsigma of the species: what one facade task view costs in the cost model.
  double observation_time_s = 0.0;
  // What it is spent on. kPerTarget: each open facade target of the view (the cost model's
  // unit: a facade task view is one target). kPerView: the view as a whole, shared by its
  // targets (common/planning/README.md, "A dwell per target" measures both).
  enum class Dwell { kPerView, kPerTarget };
  Dwell dwell = Dwell::kPerView;
  // Whether the sensors aim at one target at a time (a gimbal): then the targets take turns;
  // otherwise all are observed at once and the aims only pace the dwell.
  bool aim_each_target = false;
  double min_aim_s = 0.5;           // shortest look at anything: one scan period of the simulated LiDARs
  double settle_s = 2.0;            // map lag: coverage is judged this long after the observation
  // A new round keeps the stretch being worked on: the old route's views that followed the leg
  // (or the spot being observed) within this distance of it (straight and along the path), and that the new route still
  // has, come next in their old order. 0: only the leg is kept.
  double keep_stretch_m = 5.0;
  bool record_judgements = false;   // keep a TargetJudgement per judged target (for the trace)
  // The exploration region: ground at the frontier needs a look only where what lies beyond it
  // is inside (common/planning/frontier.h). Unbounded unless the team file sets one.
  Eigen::AlignedBox3d region = PlannerOptions::unbounded();
  // The leg being driven gives way to a new route's first view that is this much nearer by path.
  double switch_gain_m = 3.0;
};

// How the driver reports its motion (a v1::MotionState without the protobuf).
enum class DriveState { kIdle, kMoving, kBlocked, kStopped };

// What the robot should do now: follow `path` (its goal's look_at aims the sensors). While
// observing, the path is the spot the robot stands on.
struct MotionOrder {
  ExecutablePlan path;
  bool observing = false;
};

struct FollowerCounters {
  int views_reached = 0;
  int views_observed = 0;       // facade views dwelt at
  int views_skipped = 0;        // blocked or stuck on the way
  int views_observed_short = 0; // facade views observed from within reach_m of a spot the robot could not get nearer to
  int views_without_path = 0;   // no path from here
  int views_cut_off = 0;        // a path only through what `keep_off` excludes (an attempt)
  int views_done_before = 0;    // every target complete or given up before the robot got there
  int dwells_cut_short = 0;     // every target complete before the dwell was over
  int targets_not_aimed = 0;    // a gimbal's aims beyond a view's dwell: not looked at, not judged
  int legs_kept = 0;            // new routes that kept the leg being driven first
  int legs_switched = 0;        // new routes whose first view was much nearer than the leg's
  int stretch_views_kept = 0;   // views a new route kept in the old order after the leg
  double observing_s = 0.0;     // time spent standing and observing
  // Targets of observations judged a settle time later, and those of them complete by then
  // (what a dwell achieves in a mission; bench_view_efficacy measures it off-line).
  int targets_judged = 0;
  int targets_complete_when_judged = 0;
};

// One target judged a settle time after it was observed: what the map said of it then, and
// how the spot it was observed from stood to it (the trace's "judged" list; why dwells fail).
struct TargetJudgement {
  uint64_t target = 0;
  bool complete = false;
  int voxels = 0;
  int covered_voxels = 0;
  int gap = 0;                 // core::CoverageGap of most incomplete voxels
  double distance_m = 0.0;     // spot to target centre
  double incidence_deg = 0.0;  // between the target normal and the direction back to the spot
  double elevation_deg = 0.0;  // of the target centre seen from the spot (sensor height not added)
};

class RouteFollower {
 public:
  // `path_species`: the species index whose graph levels the paths use.
  RouteFollower(FollowerOptions options, int path_species);

  // A new route (a planning round) for the robot at `position`. The leg being driven (unless
  // the new first view is switch_gain_m nearer by path) and an observation in progress are
  // finished first; the new route's views at the same spot join them, and the views of the
  // stretch that followed them come next (FollowerOptions::keep_stretch_m).
  void set_route(std::vector<TaskView> route, const Eigen::Vector3d& position, const highlevel::HighLevelMap& map);
  void set_path_species(int species) { species_ = species; }
  // Drops the route, the leg and any observation (another planner takes over).
  void clear();

  // One control cycle at sim time `now_s`. Returns the order to send when it changed (a new
  // path, a new aim, or an empty path to stand still when a blocked robot has nothing left to
  // drive to); nullopt when the last order stands. `keep_off`: vertices no path may
  // enter besides those the robot was blocked at (e.g. around a silent teammate).
  std::optional<MotionOrder> step(double now_s, const Eigen::Vector3d& position, DriveState state,
                                  const highlevel::HighLevelMap& map, const std::unordered_set<uint64_t>& keep_off,
                                  GiveUpLedger& ledger);

  // No view left to drive to or observe (observations may still be settling).
  bool finished() const { return next_ >= route_.size() && !observing_; }
  size_t views_left() const { return route_.size() - std::min(route_.size(), next_) + (observing_ ? 1 : 0); }
  bool observing() const { return observing_; }
  const std::vector<TaskView>& route() const { return route_; }
  // The views still ahead: the one being driven to (or past the spot being observed) onwards.
  std::span<const TaskView> views_ahead() const {
    return std::span<const TaskView>(route_).subspan(std::min(route_.size(), next_));
  }
  const FollowerCounters& counters() const { return counters_; }
  // Where the robot stands for `view`: the clearance waypoint of its vertex for this species,
  // where its executable path ends (up to ClearanceOptions::max_shift_m from the vertex's
  // centre, away from walls and the rim of the known ground), else the view's position.
  Eigen::Vector3d standing_spot(const TaskView& view, const highlevel::HighLevelMap& map) const;
  // The judgements since the last call (the trace writes them once per round).
  std::vector<TargetJudgement> take_judgements() { return std::exchange(judgements_, {}); }

 private:
  struct PendingCheck {  // targets observed from `spot`, judged at `due_s`
    std::vector<uint64_t> targets;
    Eigen::Vector3d spot;
    double due_s;
  };

  // What to do now besides holding (step() adds that): nullopt when the last order stands.
  std::optional<MotionOrder> next_order(double now_s, const Eigen::Vector3d& position,
                                        const highlevel::HighLevelMap& map,
                                        const std::unordered_set<uint64_t>& keep_off, GiveUpLedger& ledger);
  static MotionOrder hold(const Eigen::Vector3d& position);
  std::optional<MotionOrder> drive(const Eigen::Vector3d& position, const highlevel::HighLevelMap& map,
                                   const std::unordered_set<uint64_t>& keep_off, GiveUpLedger& ledger);
  // `first_from_here`: the next view is observed from `position` though not within reach of it.
  std::optional<MotionOrder> begin_observing(double now_s, const Eigen::Vector3d& position,
                                             const highlevel::HighLevelMap& map, const GiveUpLedger& ledger,
                                             bool first_from_here = false);
  std::optional<MotionOrder> aim(size_t target_index, const Eigen::Vector3d& position);
  // Queues a facade target to aim at (once).
  void add_aim(uint64_t target, const highlevel::HighLevelMap& map);
  // How long one aim of this dwell lasts at most, for `facade_views` views with open targets;
  // with kPerView, aims that do not fit at min_aim_s each are dropped.
  double plan_aims(int facade_views);
  void finish_observing(double now_s, const Eigen::Vector3d& position);
  // Whether `target` was observed from within `distinct_m` of `position` and is not judged yet.
  bool awaiting_judgement(uint64_t target, const Eigen::Vector3d& position, double distinct_m) const;
  // A try at the view that did not observe it, for each of its incomplete targets.
  void fail_targets(const TaskView& view, const highlevel::HighLevelMap& map, GiveUpLedger& ledger);
  void skip_current(const Eigen::Vector3d& position, const highlevel::HighLevelMap& map, GiveUpLedger& ledger);
  void track_progress(double now_s, const Eigen::Vector3d& position, DriveState state);
  static TargetJudgement judgement(const highlevel::Supervoxel& sv, const Eigen::Vector3d& spot, bool complete);
  void judge(double now_s, const highlevel::HighLevelMap& map, GiveUpLedger& ledger);
  void keep_stretch(size_t at, const std::vector<Eigen::Vector3d>& stretch);
  // Within reach_m (observe_reach_m for facade and frontier views) of its standing spot.
  bool reached(const TaskView& view, const Eigen::Vector3d& position, const highlevel::HighLevelMap& map) const;
  // Along the executable path (infinite without one).
  double path_length(const Eigen::Vector3d& from, const TaskView& view, const highlevel::HighLevelMap& map) const;

  FollowerOptions options_;
  int species_;
  std::vector<TaskView> route_;
  size_t next_ = 0;  // the view being driven to

  // Observing: the view(s) reached, their open facade targets to aim at, the clock.
  struct Aim {
    uint64_t target;
    Eigen::Vector3d at;
  };
  bool observing_ = false;
  std::vector<uint64_t> observed_targets_;
  std::vector<Aim> aims_;
  size_t aim_index_ = 0;
  double aim_start_s_ = 0.0;
  double aim_s_ = 0.0;  // how long one aim lasts at most (set when the dwell begins)
  double observe_start_s_ = 0.0;
  Eigen::Vector3d observe_spot_ = Eigen::Vector3d::Zero();
  double last_step_s_ = 0.0;

  std::vector<PendingCheck> pending_;

  // Driving: progress, blocked time, the trail to back off along, vertices to avoid.
  bool driving_ = false;  // a path to route_[next_] was sent
  Eigen::Vector3d progress_pos_ = Eigen::Vector3d::Zero();
  double progress_s_ = -1.0;
  double blocked_since_s_ = -1.0;
  bool blocked_seen_ = false;
  std::vector<Eigen::Vector3d> trail_;
  std::optional<Eigen::Vector3d> backoff_;
  bool backing_off_ = false;  // the order sent is the back-off leg to *backoff_
  bool holding_ = false;      // the order sent is to stand still (nothing left, was blocked)
  std::unordered_set<uint64_t> avoid_;
  std::vector<uint64_t> path_keys_;
  std::vector<Eigen::Vector3d> path_points_;

  FollowerCounters counters_;
  std::vector<TargetJudgement> judgements_;
};

}  // namespace hexplore::planning
