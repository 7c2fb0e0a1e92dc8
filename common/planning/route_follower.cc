#include "common/planning/route_follower.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/planning/executable_path.h"
#include "common/planning/frontier.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {
namespace {

double horizontal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).head<2>().norm(); }
// Within `reach_m` on the same level: a spot on the floor above a robot is not reached from
// beneath it (multi-building seed 5: a SLUGCAT on the ground floor was handed views upstairs
// right above it), and two views a storey apart are not one view.
bool at_spot(const Eigen::Vector3d& spot, const Eigen::Vector3d& p, double reach_m) {
  return horizontal(spot, p) <= reach_m && same_level(spot, p);
}

// Whether a target still needs looking at: in the map, incomplete (or at the frontier) and not
// given up.
bool open_target(uint64_t key, const highlevel::HighLevelMap& map, const GiveUpLedger& ledger,
                 const Eigen::AlignedBox3d& region) {
  const highlevel::Supervoxel* sv = map.find(key);
  return sv && needs_look(map, *sv, region) && !ledger.given_up(key, sv->voxel_count);
}
bool open_view(const TaskView& v, const highlevel::HighLevelMap& map, const GiveUpLedger& ledger,
               const Eigen::AlignedBox3d& region) {
  return std::any_of(v.targets.begin(), v.targets.end(), [&](uint64_t t) { return open_target(t, map, ledger, region); });
}

constexpr double kProgressM = 0.5;    // moving this far counts as progress
constexpr double kTrailStepM = 0.5;   // trail points are this far apart
constexpr size_t kTrailLength = 12;
constexpr double kBackoffM = 1.0;     // back off to a trail point at least this far away
constexpr double kBackedOffM = 0.3;   // the back-off leg ends this close to its point

}  // namespace

RouteFollower::RouteFollower(FollowerOptions options, int path_species) : options_(options), species_(path_species) {}

void RouteFollower::set_route(std::vector<TaskView> route, const Eigen::Vector3d& position,
                              const highlevel::HighLevelMap& map) {
  // The leg being driven is finished first: a new round may reorder what comes after it, but
  // turning round every round (the map grows, clusters and their order change) reaches
  // nothing. It stays first, in the new route's copy when it has one at the same spot, unless
  // the new route's first view is nearer by path by switch_gain_m: then the robot turns to it
  // (e2e scene: standing in the room's doorway, the robot kept a leg round the outside of the
  // room, 15 m, and came back for the view inside it, 3 m away). Every such switch shortens the
  // way to the goal, so legs cannot take turns.
  std::optional<TaskView> leg;
  if (driving_ && next_ < route_.size()) leg = route_[next_];
  if (leg && !route.empty() && !at_spot(route.front().position, leg->position, options_.reach_m) &&
      path_length(position, route.front(), map) + options_.switch_gain_m < path_length(position, *leg, map)) {
    leg.reset();
    ++counters_.legs_switched;
  }
  // So does the stretch after it: in half the rounds the new route's first cluster lies more
  // than 5 m from the old one's before the robot got there (tools/report/route_churn.py), and a
  // robot that follows every new head drives back and forth between neighbourhoods. The
  // stretch is measured along paths too: a view behind a wall is not "just after" the leg.
  std::vector<Eigen::Vector3d> stretch;
  if (leg || observing_) {
    const Eigen::Vector3d anchor = leg ? leg->position : observe_spot_;
    for (size_t i = next_ + (leg ? 1 : 0); i < route_.size(); ++i) {
      if (horizontal(route_[i].position, anchor) > options_.keep_stretch_m ||
          path_length(anchor, route_[i], map) > options_.keep_stretch_m)
        break;
      stretch.push_back(route_[i].position);
    }
  }
  route_ = std::move(route);
  next_ = 0;
  if (leg) {
    const auto same = std::find_if(route_.begin(), route_.end(), [&](const TaskView& v) {
      return at_spot(v.position, leg->position, options_.reach_m);
    });
    if (same != route_.end()) std::rotate(route_.begin(), same, same + 1);
    else route_.insert(route_.begin(), *leg);
    ++counters_.legs_kept;
    keep_stretch(1, stretch);
    // The path to it is planned again (what to keep off may have changed since).
    driving_ = false;
    return;
  }
  driving_ = false;
  progress_s_ = -1.0;
  // An observation in progress is finished first (the cost model paid for it); views of the
  // new route at the spot being observed are part of it.
  while (observing_ && next_ < route_.size() && reached(route_[next_], observe_spot_, map)) {
    const TaskView& view = route_[next_++];
    for (uint64_t t : view.targets) {
      if (std::find(observed_targets_.begin(), observed_targets_.end(), t) != observed_targets_.end()) continue;
      observed_targets_.push_back(t);
      if (view.facade) add_aim(t, map);
    }
  }
  keep_stretch(next_, stretch);
}

double RouteFollower::path_length(const Eigen::Vector3d& from, const TaskView& view,
                                  const highlevel::HighLevelMap& map) const {
  const ExecutablePlan path = executable_path(map.graph(), from, species_, view, &avoid_);
  if (!path.valid) return std::numeric_limits<double>::infinity();
  double length = 0.0;
  Eigen::Vector3d at = from;
  for (const auto& w : path.waypoints) {
    length += horizontal(at, w);
    at = w;
  }
  return length;
}

Eigen::Vector3d RouteFollower::standing_spot(const TaskView& view, const highlevel::HighLevelMap& map) const {
  return map.graph().waypoint(view.ground_key, species_).value_or(view.position);
}

bool RouteFollower::reached(const TaskView& view, const Eigen::Vector3d& position,
                            const highlevel::HighLevelMap& map) const {
  const double reach = view.facade || view.frontier ? options_.observe_reach_m : options_.reach_m;
  return at_spot(standing_spot(view, map), position, reach);
}

void RouteFollower::keep_stretch(size_t at, const std::vector<Eigen::Vector3d>& stretch) {
  // Only views the new route still has move (the others are complete, given up or another
  // robot's now); each old view takes the first unmoved new view at its spot.
  size_t kept = at;
  for (const auto& p : stretch) {
    const auto it = std::find_if(route_.begin() + static_cast<std::ptrdiff_t>(kept), route_.end(),
                                 [&](const TaskView& v) { return at_spot(v.position, p, options_.reach_m); });
    if (it == route_.end()) continue;
    std::rotate(route_.begin() + static_cast<std::ptrdiff_t>(kept), it, it + 1);
    ++kept;
  }
  counters_.stretch_views_kept += static_cast<int>(kept - at);
}

void RouteFollower::clear() {
  route_.clear();
  next_ = 0;
  driving_ = false;
  backing_off_ = false;
  backoff_.reset();
  observing_ = false;
  progress_s_ = -1.0;
}

std::optional<MotionOrder> RouteFollower::step(double now_s, const Eigen::Vector3d& position, DriveState state,
                                               const highlevel::HighLevelMap& map,
                                               const std::unordered_set<uint64_t>& keep_off, GiveUpLedger& ledger) {
  if (observing_) counters_.observing_s += std::max(0.0, now_s - last_step_s_);
  last_step_s_ = now_s;
  judge(now_s, map, ledger);
  track_progress(now_s, position, state);
  std::optional<MotionOrder> order = next_order(now_s, position, map, keep_off, ledger);
  if (order) {
    holding_ = false;
    return order;
  }
  // Nothing left to drive to while the last order still pushes the robot into what blocked it
  // (the leg it skipped, or a back-off that was blocked too): the driver keeps trying that path
  // and the robot stays BLOCKED while it has no work (multi-building, seed 1: slugcat1 for 69 s).
  // Hold where it stands, once.
  if (state == DriveState::kBlocked && !driving_ && !backing_off_ && !holding_) {
    holding_ = true;
    return hold(position);
  }
  return std::nullopt;
}

MotionOrder RouteFollower::hold(const Eigen::Vector3d& position) {
  MotionOrder order;  // an empty path: the safety layer stops the robot ("no path")
  order.path.goal.position = position;
  return order;
}

std::optional<MotionOrder> RouteFollower::next_order(double now_s, const Eigen::Vector3d& position,
                                                     const highlevel::HighLevelMap& map,
                                                     const std::unordered_set<uint64_t>& keep_off,
                                                     GiveUpLedger& ledger) {
  if (observing_) {
    // Each aim lasts its time (plan_aims: the target's observation time, or its share of the
    // view's) and ends early once its target is complete (or given up): a look at one target
    // often completes the next ones too, whose aims are then passed over. The dwell is over
    // when the aims are, or as soon as every target it is for is complete (the map lags the
    // scans by about a settle time, so this never cuts a dwell short by more).
    const size_t was = aim_index_;
    const bool time_left = was < aims_.size() && now_s - aim_start_s_ < aim_s_;
    while (aim_index_ < aims_.size() &&
           (!open_target(aims_[aim_index_].target, map, ledger, options_.region) || now_s - aim_start_s_ >= aim_s_)) {
      ++aim_index_;
      aim_start_s_ = now_s;
    }
    const bool all_done = std::none_of(observed_targets_.begin(), observed_targets_.end(),
                                       [&](uint64_t t) { return open_target(t, map, ledger, options_.region); });
    const bool aims_over = aim_index_ >= aims_.size() && now_s - observe_start_s_ >= options_.min_aim_s;
    if (aims_over || all_done) {
      if (all_done && time_left) ++counters_.dwells_cut_short;
      finish_observing(now_s, position);
      return drive(position, map, keep_off, ledger);
    }
    return aim_index_ != was && aim_index_ < aims_.size() ? aim(aim_index_, position) : std::nullopt;
  }
  if (backing_off_) {
    // The back-off leg ends at its point, or where it cannot go on (blocked there too, or no
    // progress); the path to the next view is planned from wherever that is.
    const bool there = horizontal(*backoff_, position) <= kBackedOffM;
    const bool blocked = blocked_since_s_ >= 0.0 && now_s - blocked_since_s_ >= options_.blocked_s;
    const bool stuck = progress_s_ >= 0.0 && now_s - progress_s_ >= options_.stuck_s;
    if (!there && !blocked && !stuck) return std::nullopt;
    backing_off_ = false;
    backoff_.reset();
    return drive(position, map, keep_off, ledger);
  }
  if (next_ >= route_.size()) return std::nullopt;
  if (driving_ && !open_view(route_[next_], map, ledger, options_.region)) {
    // Its targets got complete (a teammate, or scans in passing) or given up: on to the next.
    ++counters_.views_done_before;
    ++next_;
    driving_ = false;
  }
  if (next_ >= route_.size()) return std::nullopt;
  if (reached(route_[next_], position, map)) {
    std::optional<MotionOrder> order = begin_observing(now_s, position, map, ledger);
    return observing_ ? order : drive(position, map, keep_off, ledger);  // ground views: on to the next
  }
  if (!driving_) return drive(position, map, keep_off, ledger);
  const bool blocked = blocked_since_s_ >= 0.0 && now_s - blocked_since_s_ >= options_.blocked_s;
  const bool stuck = progress_s_ >= 0.0 && now_s - progress_s_ >= options_.stuck_s;
  if (!blocked && !stuck) return std::nullopt;
  if (route_[next_].facade && at_spot(standing_spot(route_[next_], map), position, options_.reach_m)) {
    // Within a metre of a spot it cannot get nearer to (its body against the edge of the known
    // ground or a wall): a look from here sees what the spot would, give or take a few degrees,
    // where a skip would count an attempt without a look (default mission: 39 of the MR1000's 62
    // skips, at views on the edge of the ground plane it stopped half a metre short of).
    ++counters_.views_observed_short;
    std::optional<MotionOrder> order = begin_observing(now_s, position, map, ledger, /*first_from_here=*/true);
    return observing_ ? order : drive(position, map, keep_off, ledger);
  }
  skip_current(position, map, ledger);
  return drive(position, map, keep_off, ledger);
}

std::optional<MotionOrder> RouteFollower::begin_observing(double now_s, const Eigen::Vector3d& position,
                                                          const highlevel::HighLevelMap& map,
                                                          const GiveUpLedger& ledger, bool first_from_here) {
  // Every consecutive view within reach is observed from here at once, for its targets that
  // are still open; a view with none left costs no dwell.
  observed_targets_.clear();
  aims_.clear();
  int facade_views = 0;
  for (bool take = first_from_here; next_ < route_.size() && (take || reached(route_[next_], position, map));
       ++next_, take = false) {
    const TaskView& v = route_[next_];
    ++counters_.views_reached;
    const size_t aims_before = aims_.size();
    for (uint64_t t : v.targets) {
      // Observed from here a moment ago and not judged yet: a second look from the same spot
      // would only delay the verdict (the next view of it stands elsewhere if it fails).
      if (!open_target(t, map, ledger, options_.region) || awaiting_judgement(t, position, ledger.rules().distinct_m)) continue;
      observed_targets_.push_back(t);
      if (v.facade) add_aim(t, map);
    }
    if (aims_.size() > aims_before) ++facade_views;
  }
  driving_ = false;
  if (aims_.empty() || options_.observation_time_s <= 0.0) {  // ground views: observed on arrival
    aims_.clear();
    pending_.push_back({observed_targets_, position, now_s + options_.settle_s});
    return std::nullopt;
  }
  aim_s_ = plan_aims(facade_views);
  observing_ = true;
  observe_start_s_ = now_s;
  aim_start_s_ = now_s;
  observe_spot_ = position;
  ++counters_.views_observed;
  return aim(0, position);
}

void RouteFollower::add_aim(uint64_t target, const highlevel::HighLevelMap& map) {
  const highlevel::Supervoxel* sv = map.find(target);
  if (sv == nullptr || !sv->facade()) return;
  if (std::any_of(aims_.begin(), aims_.end(), [&](const Aim& a) { return a.target == target; })) return;
  aims_.push_back({target, sv->center});
}

double RouteFollower::plan_aims(int facade_views) {
  const double obs = options_.observation_time_s;
  if (options_.dwell == FollowerOptions::Dwell::kPerTarget) {
    // A gimbal gives each target its own time, and at least one scan; sensors that see them
    // all at once spend the sum of their times on all (the dwell lasts at least one scan).
    return options_.aim_each_target ? std::max(obs, options_.min_aim_s) : obs;
  }
  // One observation time per view, shared: a sweep gives each aim at least one scan, so with
  // less time the first aims only.
  const double dwell = std::max(1, facade_views) * obs;
  const size_t fit = std::max<size_t>(1, size_t(dwell / std::max(1e-3, options_.min_aim_s)));
  if (aims_.size() > fit) {
    if (options_.aim_each_target) {
      // A gimbal never points at the targets of the aims that do not fit: no verdict on them
      // (it would count a look that did not happen as a failed attempt; multi-building, seed 1:
      // 31 of one view's 51 targets at 57 s), so they stay open and are planned again.
      for (size_t i = fit; i < aims_.size(); ++i) std::erase(observed_targets_, aims_[i].target);
      counters_.targets_not_aimed += int(aims_.size() - fit);
    }
    aims_.resize(fit);
  }
  return dwell / double(aims_.size());
}

std::optional<MotionOrder> RouteFollower::aim(size_t target_index, const Eigen::Vector3d& position) {
  aim_index_ = target_index;
  MotionOrder order;
  order.observing = true;
  order.path.valid = true;
  order.path.waypoints = {position};
  order.path.goal.position = position;
  order.path.goal.look_at = aims_[target_index].at;
  order.path.goal.facade = true;
  return order;
}

void RouteFollower::finish_observing(double now_s, const Eigen::Vector3d& position) {
  pending_.push_back({observed_targets_, observe_spot_, now_s + options_.settle_s});
  observing_ = false;
  progress_pos_ = position;
  progress_s_ = now_s;
}

std::optional<MotionOrder> RouteFollower::drive(const Eigen::Vector3d& position, const highlevel::HighLevelMap& map,
                                                const std::unordered_set<uint64_t>& keep_off, GiveUpLedger& ledger) {
  if (backoff_) {
    // Leave the spot we are stuck at first, as a leg of its own: prepended to the next path,
    // the back-off point was dropped downstream whenever that path passed right by the robot
    // (the safety layer drives on from the nearest point of a path; office scene, seed 1:
    // mr1000a drove into the same door jamb again and again).
    backing_off_ = true;
    driving_ = false;
    progress_pos_ = position;
    progress_s_ = last_step_s_;
    blocked_since_s_ = -1.0;
    MotionOrder out;
    out.path.valid = true;
    out.path.waypoints = {*backoff_};
    out.path.goal.position = *backoff_;
    return out;
  }
  std::unordered_set<uint64_t> avoid = avoid_;
  avoid.insert(keep_off.begin(), keep_off.end());
  const size_t first = next_;
  for (; next_ < route_.size(); ++next_) {
    if (!open_view(route_[next_], map, ledger, options_.region)) {
      ++counters_.views_done_before;
      continue;
    }
    ExecutablePlan path = executable_path(map.graph(), position, species_, route_[next_], &avoid);
    if (!path.valid) {
      if (!keep_off.empty() && executable_path(map.graph(), position, species_, route_[next_], &avoid_).valid) {
        // Cut off only by where a silent teammate stands (its body stays there): a try that
        // failed, as if blocked on the way. The planner does not know what the follower keeps
        // off and routes here again every round; uncounted, the robot stood still for the
        // rest of the mission (e2e kill test: two views beyond the killed robot, 915 s).
        fail_targets(route_[next_], map, ledger);
        ++counters_.views_cut_off;
        continue;
      }
      // No way there from here for us (maybe only around a spot we were blocked at): skip it
      // without counting it against the target, which a teammate may reach.
      ++counters_.views_without_path;
      continue;
    }
    path_keys_ = path.keys;
    path_points_ = path.waypoints;
    driving_ = true;
    progress_pos_ = position;
    progress_s_ = last_step_s_;
    blocked_since_s_ = -1.0;
    return MotionOrder{std::move(path), false};
  }
  if (!avoid_.empty()) {
    // The spots we avoid cut us off from every view: forget them and try the route again.
    avoid_.clear();
    next_ = first;
    return drive(position, map, keep_off, ledger);
  }
  driving_ = false;
  return std::nullopt;
}

void RouteFollower::skip_current(const Eigen::Vector3d& position, const highlevel::HighLevelMap& map,
                                 GiveUpLedger& ledger) {
  if (blocked_seen_ || blocked_since_s_ >= 0.0) {
    // Keep off the vertex we were driving to when blocked: the path point after the one nearest to us.
    size_t near = 0;
    for (size_t i = 1; i < path_points_.size(); ++i)
      if (horizontal(path_points_[i], position) < horizontal(path_points_[near], position)) near = i;
    for (size_t i = near; i < path_keys_.size(); ++i)
      if (horizontal(path_points_[i], position) > 0.4) {
        avoid_.insert(path_keys_[i]);
        break;
      }
  }
  // Whatever holds us here, leave the way we came before heading for the next view.
  for (auto it = trail_.rbegin(); it != trail_.rend(); ++it)
    if (horizontal(*it, position) >= kBackoffM) {
      backoff_ = *it;
      break;
    }
  fail_targets(route_[next_], map, ledger);
  ++counters_.views_skipped;
  ++next_;
  driving_ = false;
  blocked_since_s_ = -1.0;
  blocked_seen_ = false;
}

void RouteFollower::fail_targets(const TaskView& view, const highlevel::HighLevelMap& map, GiveUpLedger& ledger) {
  for (uint64_t t : view.targets) {
    const highlevel::Supervoxel* sv = map.find(t);
    if (sv && needs_look(map, *sv, options_.region)) ledger.failed(t, sv->voxel_count);
  }
}

void RouteFollower::track_progress(double now_s, const Eigen::Vector3d& position, DriveState state) {
  if (trail_.empty() || horizontal(trail_.back(), position) >= kTrailStepM) {
    trail_.push_back(position);
    if (trail_.size() > kTrailLength) trail_.erase(trail_.begin());
  }
  if (!(driving_ || backing_off_) || progress_s_ < 0.0 || horizontal(position, progress_pos_) > kProgressM) {
    progress_pos_ = position;
    progress_s_ = now_s;
    blocked_seen_ = false;
  }
  if (state != DriveState::kBlocked) blocked_since_s_ = -1.0;
  else if (blocked_since_s_ < 0.0) blocked_since_s_ = now_s;
  blocked_seen_ = blocked_seen_ || state == DriveState::kBlocked;
}

TargetJudgement RouteFollower::judgement(const highlevel::Supervoxel& sv, const Eigen::Vector3d& spot, bool complete) {
  TargetJudgement j;
  j.target = sv.key;
  j.complete = complete;
  j.voxels = sv.voxel_count;
  j.covered_voxels = sv.covered_voxels;
  j.gap = int(sv.gap);
  const ViewGeometry g = view_geometry(spot, Eigen::Vector3d::UnitZ(), sv.center, sv.normal);
  j.distance_m = g.distance_m;
  j.incidence_deg = g.incidence_rad * kRadToDeg;
  j.elevation_deg = g.elevation_rad * kRadToDeg;
  return j;
}

bool RouteFollower::awaiting_judgement(uint64_t target, const Eigen::Vector3d& position, double distinct_m) const {
  return std::any_of(pending_.begin(), pending_.end(), [&](const PendingCheck& c) {
    return (c.spot - position).squaredNorm() < distinct_m * distinct_m &&
           std::find(c.targets.begin(), c.targets.end(), target) != c.targets.end();
  });
}

void RouteFollower::judge(double now_s, const highlevel::HighLevelMap& map, GiveUpLedger& ledger) {
  auto due = [&](const PendingCheck& c) { return c.due_s <= now_s; };
  for (const PendingCheck& c : pending_) {
    if (!due(c)) continue;
    for (uint64_t t : c.targets) {
      const highlevel::Supervoxel* sv = map.find(t);
      if (!sv) continue;  // re-segmented away since
      ++counters_.targets_judged;
      const bool open = needs_look(map, *sv, options_.region);
      if (open) ledger.observed(t, c.spot, sv->voxel_count);
      else ++counters_.targets_complete_when_judged;
      if (options_.record_judgements) judgements_.push_back(judgement(*sv, c.spot, !open));
    }
  }
  pending_.erase(std::remove_if(pending_.begin(), pending_.end(), due), pending_.end());
}

}  // namespace hexplore::planning
