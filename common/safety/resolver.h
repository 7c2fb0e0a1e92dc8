#pragma once
// Per-robot path-conflict resolution (paper "Path-Conflict Resolution Strategy"): each cycle
// the robot's desired path is detoured around stationary teammates' boxes, checked against the
// moving teammates' shared fragments, and cut short where the robot must yield. The robot that
// would reach the conflict zone later yields; near-equal times go to the lower robot id.
// Nobody waits forever: a circle of robots waiting for each other lets its lowest id go; a
// robot blocked by this one's box makes this one go first; a yield to a robot that stopped for
// reasons of its own ends after a timeout; and of two robots blocking each other, the higher
// id steps aside. The safety layer has no map, so the spot it steps aside to may be out of
// reach (behind a wall, under a table): a give-way that gets no closer to its spot while
// approved for give_way_timeout_s is abandoned, and the next spot is sought in another
// direction.

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/safety/box_detour.h"
#include "common/safety/conflict.h"
#include "common/safety/fragment.h"
#include "common/safety/polyline.h"

namespace hexplore::safety {

// Tunables; distances in metres, times in seconds.
struct SafetyOptions {
  double eta_p_m = 2.0;              // shared fragment length (paper eta_p)
  double conflict_margin_m = 0.5;    // conflict zone = sum of body radii + this
  double obstacle_margin_m = 0.2;    // a stopped robot's box grows by own radius + this
  double detour_clearance_m = 0.2;   // detour waypoints sit this far outside the grown box
  double hard_margin_m = 0.1;        // never approach a moving teammate closer than radii + this
  double cycle_s = 0.2;              // decision period: how far both may move before the next one
  double extrapolate_m = 1.0;        // a fragment cut at eta_p continues this far straight on
  double tie_window_s = 0.5;         // arrival times in the same window tie -> lower id first
  double deadlock_timeout_s = 3.0;   // yield to a robot that stopped waiting for nobody ends then
  double stop_buffer_m = 0.1;        // yielding robots stop this far before the zone
  double min_move_m = 0.05;          // shorter approved paths are a Stop
  double sample_step_m = 0.1;        // path sampling for conflict search
  double give_way_timeout_s = 3.0;   // a give-way approved this long without getting closer is abandoned
  // A teammate whose near motion stays this far above or below this robot's (or farther, when
  // the two bodies' heights add up to more) is on another storey: a slab lies between them and
  // neither can reach the other within a fragment. 2 m: the tallest built-in body is 0.8 m, path
  // points lie on the ground while poses are body centres (half a body lower), and a storey is
  // at least 3 m; two robots on one flight are compared point by point along it anyway.
  double level_separation_m = 2.0;

  // Throws std::invalid_argument naming the first bad field.
  void validate() const;
};

enum class DecisionKind { kFollow, kStop };

// What goes to the robot driver: an approved path (FollowPath) or a Stop with its reason.
struct Decision {
  DecisionKind kind = DecisionKind::kStop;
  Path waypoints;                 // approved path, starting at the robot (kFollow)
  double speed_mps = 0.0;
  std::string reason;             // why it stopped or was cut short ("" when unrestricted)
  std::string yielding_to;        // robot waited for, "" when not yielding
  bool detoured = false;          // path bends around a stationary teammate
};

struct ResolverCounters {
  uint64_t conflicts_detected = 0;   // peer conflicts that newly appeared
  uint64_t yields = 0;               // times this robot started yielding to a peer
  uint64_t detours = 0;              // times a detour around a stopped peer began
  uint64_t deadlock_breaks = 0;      // yields ended by the wait-cycle or timeout rules
  uint64_t blocked = 0;              // decisions cut short before an impassable box
  uint64_t give_ways = 0;            // times this robot stepped aside for a blocked teammate
  uint64_t give_ways_abandoned = 0;  // give-ways whose spot proved out of reach (no progress)
};

class ConflictResolver {
 public:
  ConflictResolver(std::string robot_id, const Eigen::Vector3d& body_half_extents_m, SafetyOptions options);

  // One decision for a robot at `position` that wants to drive `desired_path` at `speed_mps`,
  // given the teammates' latest fragments (own id and unknown order are fine). `now_s` is any
  // monotonic clock in seconds (sim time in tests).
  Decision decide(const Eigen::Vector3d& position, const Path& desired_path, double speed_mps,
                  const std::vector<Fragment>& peers, double now_s);

  // The fragment to share after the last decision: its approved path within eta_p.
  Fragment fragment(const Eigen::Vector3d& position) const;

  // Forgets yields and conflicts (mission restart, emergency stop).
  void reset();

  const ResolverCounters& counters() const { return counters_; }
  const std::string& robot_id() const { return robot_id_; }
  double body_radius_m() const { return radius_m_; }
  const SafetyOptions& options() const { return options_; }

 private:
  struct YieldRecord {
    double since_s = 0.0;
    ConflictKind kind = ConflictKind::kCrossing;
  };

  // How far the robot may drive along its candidate path, and why not farther.
  struct Limit {
    double limit_s = std::numeric_limits<double>::infinity();  // arc length; inf = all of it
    std::string reason;
    std::string yielding_to;
  };

  // The phases of decide(), in order.
  // Teammates that claim to drive but have not moved 0.2 m in 15 s, as stopped (see last_move_).
  std::vector<Fragment> with_frozen_as_stopped(const std::vector<Fragment>& peers, double now_s);
  // Whether `peer` is on another storey than a robot about to drive `own_near` (see
  // SafetyOptions::level_separation_m). Distances elsewhere in the resolver are horizontal, so
  // without this a robot upstairs would yield to, and detour round, a teammate standing below it
  // (multi-building seed 5: 144 s held over an idle robot on the floor beneath).
  bool on_another_level(const Path& own_near, const Fragment& peer) const;
  // The desired path ahead of the robot: looked for near where it was last time, unless it is
  // clearly elsewhere (a long detour, a relocalisation), then anywhere on the path.
  Path remaining_desired(const Eigen::Vector3d& position, const Path& desired_path, double speed_mps);
  // `remaining` (or the detour being followed) bent around the stopped teammates' boxes.
  DetourResult detour_stopped(const Eigen::Vector3d& position, const Path& desired_path, const Path& remaining,
                              const std::vector<ObstacleBox>& boxes);
  // Starts, keeps or abandons making room for a blocked teammate (give_way_to_, give_way_spot_).
  void update_give_way(const Eigen::Vector3d& position, const DetourResult& detour,
                       const std::vector<const Fragment*>& peers, const std::vector<ObstacleBox>& boxes,
                       double since_last_s);
  // Where the robot must stop on `near` to yield to moving teammates (and stopped ones it
  // still waits for); starts and ends yields.
  Limit yield_limit(const Path& near, const std::vector<const Fragment*>& peers, double speed_mps, double now_s);
  // Whether an ongoing yield to `peer` goes on, or a deadlock rule ends it.
  bool still_yielding(const Fragment& peer, const YieldRecord& record, const std::vector<const Fragment*>& peers,
                      double now_s);
  // Last line of defence against inconsistent views: never close in on a teammate's body beyond
  // the hard distance (or beyond the current distance when already inside it); lowers
  // `limit_s` and sets `why`. A teammate known only from an older fragment may be anywhere on
  // its trail. Stopped teammates too: their box is shrunk when the robot starts inside it
  // (detours, making room), and a box's corners lie farther from the body than its faces, so
  // sliding along the shrunk face could still reach the body. Returns the stopped teammate that
  // cut the path, if one did.
  const Fragment* hold_off(const Eigen::Vector3d& position, const Path& path, double speed_mps,
                           const std::vector<const Fragment*>& peers, double& limit_s, std::string& why) const;
  // Straight out of `held_by`'s grown box, away from its body; nullopt when not inside it.
  std::optional<Path> step_out_of(const Eigen::Vector3d& position, const Fragment& held_by) const;
  // The decision: `candidate` cut at the limit, with its reason.
  Decision finish(const Path& candidate, Limit limit, const std::string& giving_way_to, const DetourResult& detour,
                  double speed_mps);

  Decision stop(std::string reason, std::string yielding_to);
  // A spot 1-4 m away, clear of `blocked`'s wanted path and reachable in a straight line,
  // not in a direction a give-way of this standoff already failed in.
  std::optional<Eigen::Vector3d> find_room(const Eigen::Vector3d& position, const Fragment& blocked,
                                           const std::vector<ObstacleBox>& boxes) const;
  // Follows "waits for" from `first` through the peers; when the chain leads back to this
  // robot, returns the lowest id on the circle, else "".
  std::string lowest_in_wait_cycle(const std::string& first, const std::vector<const Fragment*>& peers) const;

  std::string robot_id_;
  Eigen::Vector3d half_extents_m_;
  double radius_m_;
  SafetyOptions options_;
  // Where each teammate was last seen to move, and when: a teammate whose fragment says it
  // drives but that has not moved 0.2 m in 15 s is taken as stopped (seen
  // in e2e: an idle robot whose safety kept its last approved path while the driver stood at
  // the goal held a teammate in a head-on yield for 300 s).
  struct LastMove {
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    double since_s = 0.0;
  };
  std::map<std::string, LastMove> last_move_;
  std::map<std::string, YieldRecord> yields_;   // peers this robot currently yields to
  std::set<std::string> conflicting_;           // peers in conflict at the last decision
  bool stationary_ = true;
  bool was_detoured_ = false;
  Path detour_path_;                            // the detour being followed
  Path detour_for_;                             // the desired path it was made for
  Path wanted_near_;                            // near desired path while blocked (shared)
  Path progress_path_;                          // desired path whose progress is tracked
  double progress_s_ = 0.0;                     // arc length reached along it
  std::string give_way_to_;                     // teammate this robot is making room for
  Eigen::Vector3d give_way_spot_ = Eigen::Vector3d::Zero();
  double give_way_best_m_ = 0.0;                // closest the robot came to the spot
  double give_way_stalled_s_ = 0.0;             // time approved towards it without getting closer
  bool give_way_approved_ = false;              // the last decision drove towards the spot
  std::vector<Eigen::Vector2d> failed_give_way_dirs_;  // unit directions that led nowhere
  double last_decide_s_ = 0.0;
  Decision last_;
  ResolverCounters counters_;
};

}  // namespace hexplore::safety
