#pragma once
// Where a gimbal LiDAR looks while its robot drives. At a facade view the gimbal aims at the
// view's targets (RouteFollower); on the way there it aimed at the goal view's first target,
// often from far off, out of J or behind a wall. Looking ahead pays: a target the robot is
// about to dwell for, seen on the approach, is often complete before it arrives, and the
// dwell is cut short or skipped. So on the way the gimbal aims at the first target ahead on
// the route (the goal view's targets, then the next views', in route order) that passes J
// from where the robot is (within the species' range, inside the angle limits, line of sight
// clear), keeps it for `hold_s` (a few scans) unless it completes or drops out of view, and
// gives no target more than `budget_s` of such looks (its observation time: what stays open
// after that needs its dwell). With nothing ahead in view the caller keeps the goal's aim.
// (Aiming instead at whatever open target is seen best from here, route or not, was measured
// worse: common/planning/README.md, "Where the gimbal looks on the way".)

#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"
#include "common/planning/capabilities.h"
#include "common/planning/give_up_ledger.h"

namespace hexplore::planning {

struct PassingAimOptions {
  double range_m = 27.0;   // the species' observation range (l_th)
  double hold_s = 2.0;     // an aim is kept this long: four scans of the 2 Hz LiDAR
  double budget_s = 10.0;  // passing looks at one target add up to at most this
};

class PassingAim {
 public:
  PassingAim(PassingAimOptions aim, PlannerOptions planner);

  // One look at sim time `now_s` from `position` (call about once a second while driving);
  // `ahead`: the targets of the views ahead on the route, in route order. Returns the point
  // the gimbal should aim at (a target's centre), or nullopt when none of them is in view.
  std::optional<Eigen::Vector3d> step(double now_s, const Eigen::Vector3d& position,
                                      const highlevel::HighLevelMap& map, const GiveUpLedger& ledger,
                                      std::span<const uint64_t> ahead);
  // The robot stopped driving (it observes at a view): the next step chooses afresh.
  void pause() { current_ = 0; }

  uint64_t target() const { return current_; }  // 0: none
  int aims() const { return aims_; }             // targets aimed at so far

 private:
  // Vis of `sv` from `sensor` when it is an open facade target passing J there (no line of
  // sight test); 0 else.
  double score(const highlevel::Supervoxel& sv, const Eigen::Vector3d& sensor, const GiveUpLedger& ledger) const;

  PassingAimOptions aim_;
  PlannerOptions planner_;
  uint64_t current_ = 0;
  Eigen::Vector3d current_at_ = Eigen::Vector3d::Zero();
  double since_s_ = 0.0;
  double last_s_ = -1.0;
  std::unordered_map<uint64_t, double> looked_s_;  // passing looks per target so far
  int aims_ = 0;
};

}  // namespace hexplore::planning
