#include "common/safety/resolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "common/safety/box_detour.h"

namespace hexplore::safety {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A give-way that led nowhere rules out spots within this angle of its direction: whatever
// stopped the robot (a wall, a table) is most likely in the way of those too.
constexpr double kFailedConeRad = 50.0 * M_PI / 180.0;

// Priority of a robot at a conflict: earlier arrival window first, then the lower id. A total
// order, so three or more robots at one crossing can never wait for each other in a cycle.
struct Priority {
  double window;
  std::string id;
  bool operator<(const Priority& o) const { return window != o.window ? window < o.window : id < o.id; }
};

Priority priority_of(double t_s, const std::string& id, double tie_window_s) {
  return {std::isfinite(t_s) ? std::floor(t_s / tie_window_s) : kInf, id};
}

void require_positive(double v, const char* field, bool allow_zero = false) {
  if (!std::isfinite(v) || v < 0.0 || (!allow_zero && v == 0.0)) {
    throw std::invalid_argument(std::string("SafetyOptions.") + field + " must be " +
                                (allow_zero ? "non-negative" : "positive") + ", got " + std::to_string(v));
  }
}

}  // namespace

void SafetyOptions::validate() const {
  require_positive(eta_p_m, "eta_p_m");
  require_positive(conflict_margin_m, "conflict_margin_m", true);
  require_positive(obstacle_margin_m, "obstacle_margin_m", true);
  require_positive(detour_clearance_m, "detour_clearance_m", true);
  require_positive(hard_margin_m, "hard_margin_m", true);
  require_positive(cycle_s, "cycle_s", true);
  require_positive(extrapolate_m, "extrapolate_m", true);
  require_positive(tie_window_s, "tie_window_s");
  require_positive(deadlock_timeout_s, "deadlock_timeout_s");
  require_positive(stop_buffer_m, "stop_buffer_m", true);
  require_positive(min_move_m, "min_move_m");
  require_positive(sample_step_m, "sample_step_m");
  require_positive(give_way_timeout_s, "give_way_timeout_s");
  require_positive(level_separation_m, "level_separation_m");
}

ConflictResolver::ConflictResolver(std::string robot_id, const Eigen::Vector3d& body_half_extents_m,
                                   SafetyOptions options)
    : robot_id_(std::move(robot_id)),
      half_extents_m_(body_half_extents_m),
      radius_m_(body_radius_of(body_half_extents_m)),
      options_(options) {
  options_.validate();
  if (robot_id_.empty()) throw std::invalid_argument("ConflictResolver: robot id must not be empty");
}

void ConflictResolver::reset() {
  yields_.clear();
  give_way_to_.clear();
  give_way_approved_ = false;
  failed_give_way_dirs_.clear();
  wanted_near_.clear();
  conflicting_.clear();
  stationary_ = true;
  was_detoured_ = false;
  progress_path_.clear();
  progress_s_ = 0.0;
  last_ = Decision{};
}

std::string ConflictResolver::lowest_in_wait_cycle(const std::string& first,
                                                   const std::vector<const Fragment*>& peers) const {
  std::string lowest = robot_id_;
  std::string current = first;
  for (size_t hops = 0; hops <= peers.size(); ++hops) {
    if (current == robot_id_) return lowest;
    lowest = std::min(lowest, current);
    const auto it = std::find_if(peers.begin(), peers.end(), [&](const Fragment* p) { return p->robot_id == current; });
    if (it == peers.end() || (*it)->yielding_to.empty()) return "";
    current = (*it)->yielding_to;
  }
  return "";
}

std::optional<Eigen::Vector3d> ConflictResolver::find_room(const Eigen::Vector3d& position, const Fragment& blocked,
                                                         const std::vector<ObstacleBox>& boxes) const {
  // Clear of the wanted path and of its straight continuation: stepping aside along the other
  // robot's way would only move the obstacle further down its path.
  const auto wanted = sample_path(extend_path(blocked.path(), options_.eta_p_m), options_.sample_step_m);
  const double clear = radius_m_ + blocked.body_radius_m() + options_.conflict_margin_m;
  // Nearest spot first; directions in a fixed order, so the choice is deterministic.
  for (double distance = 1.0; distance <= 4.0 + 1e-9; distance += 0.5) {
    for (int k = 0; k < 16; ++k) {
      const double angle = 2.0 * M_PI * k / 16.0;
      const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
      const bool failed_before = std::any_of(failed_give_way_dirs_.begin(), failed_give_way_dirs_.end(),
                                             [&](const Eigen::Vector2d& f) { return dir.dot(f) > std::cos(kFailedConeRad); });
      if (failed_before) continue;
      const Eigen::Vector3d spot = position + distance * Eigen::Vector3d(dir.x(), dir.y(), 0.0);
      bool ok = true;
      for (const auto& w : wanted) ok = ok && distance_xy(w.point, spot) > clear;
      if (!ok) continue;
      // Reachable in a straight line without entering another robot's box (the one being
      // made room for is left behind, so a box containing the start is shrunk as in detours).
      const DetourResult reach = detour_around({position, spot}, boxes, DetourOptions{});
      if (!reach.detoured && !reach.blocked) return spot;
    }
  }
  return std::nullopt;
}

Decision ConflictResolver::stop(std::string reason, std::string yielding_to) {
  Decision d;
  d.kind = DecisionKind::kStop;
  d.reason = std::move(reason);
  d.yielding_to = std::move(yielding_to);
  stationary_ = true;
  last_ = d;
  return d;
}

std::vector<Fragment> ConflictResolver::with_frozen_as_stopped(const std::vector<Fragment>& peers_in, double now_s) {
  // Longer than any honest wait a driving teammate's fragment shows (a yield to a third robot
  // crossing, a give-way), far shorter than a mission.
  constexpr double kStillM = 0.2;
  constexpr double kFrozenS = 15.0;
  std::vector<Fragment> adjusted;
  adjusted.reserve(peers_in.size());
  for (const auto& p : peers_in) {
    if (p.robot_id == robot_id_) continue;
    auto [it, fresh] = last_move_.try_emplace(p.robot_id, LastMove{p.position_m, now_s});
    if (fresh || p.stationary || distance_xy(p.position_m, it->second.position_m) > kStillM || now_s < it->second.since_s)
      it->second = {p.position_m, now_s};
    adjusted.push_back(p);
    if (!p.stationary && now_s - it->second.since_s > kFrozenS) {
      adjusted.back().stationary = true;
      adjusted.back().speed_mps = 0.0;
    }
  }
  return adjusted;
}

bool ConflictResolver::on_another_level(const Path& own_near, const Fragment& peer) const {
  // Lowest and highest point of each robot's near motion (the peer's: where it is, where its
  // fragment leads, and the trail it may still be on).
  const auto widen = [](double& lo, double& hi, double z) {
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  };
  double own_lo = kInf, own_hi = -kInf;
  for (const auto& p : own_near) widen(own_lo, own_hi, p.z());
  double peer_lo = kInf, peer_hi = -kInf;
  widen(peer_lo, peer_hi, peer.position_m.z());
  for (const Path* points : {&peer.waypoints_m, &peer.trail_m})
    for (const auto& p : *points) widen(peer_lo, peer_hi, p.z());
  const double gap = std::max(peer_lo - own_hi, own_lo - peer_hi);
  const double bodies = 2.0 * half_extents_m_.z() + (peer.box_max_m.z() - peer.box_min_m.z());
  return gap > std::max(options_.level_separation_m, bodies);
}

Path ConflictResolver::remaining_desired(const Eigen::Vector3d& position, const Path& desired_path, double speed_mps) {
  if (desired_path != progress_path_) {
    progress_path_ = desired_path;
    progress_s_ = 0.0;
  }
  double at_s = 0.0;
  const double window_m = options_.eta_p_m + speed_mps * options_.cycle_s;
  Path remaining = remaining_path(position, desired_path, progress_s_ - 0.5, progress_s_ + window_m, &at_s);
  double anywhere_s = 0.0;
  Path anywhere = remaining_path(position, desired_path, 0.0, kInf, &anywhere_s);
  const auto gap = [&](double s) { return distance_xy(position, point_at(desired_path, s)); };
  if (gap(at_s) > gap(anywhere_s) + 0.5) {
    remaining = std::move(anywhere);
    at_s = anywhere_s;
  }
  progress_s_ = at_s;
  return remaining;
}

DetourResult ConflictResolver::detour_stopped(const Eigen::Vector3d& position, const Path& desired_path,
                                              const Path& remaining, const std::vector<ObstacleBox>& boxes) {
  DetourOptions detour_options;
  detour_options.clearance_m = options_.detour_clearance_m;
  // Once on a detour, keep following it while the plan and the obstacles last: re-deriving it
  // from the plan every cycle would pull the robot back towards the box and make it dither.
  const bool keep_detour = was_detoured_ && !boxes.empty() && desired_path == detour_for_;
  const Path base = keep_detour ? remaining_path(position, detour_path_) : remaining;
  DetourResult detour = detour_around(base, boxes, detour_options);
  if (detour.detoured && !keep_detour) ++counters_.detours;
  detour.detoured = detour.detoured || keep_detour;
  was_detoured_ = detour.detoured && !detour.blocked;
  if (was_detoured_) {
    detour_path_ = detour.path;
    detour_for_ = desired_path;
  }
  if (detour.blocked) ++counters_.blocked;
  // A blocked robot shows teammates where it wants to go (they may have to make room).
  wanted_near_ = detour.blocked ? truncate_to_length(base, options_.eta_p_m) : Path{};
  return detour;
}

void ConflictResolver::update_give_way(const Eigen::Vector3d& position, const DetourResult& detour,
                                       const std::vector<const Fragment*>& peers,
                                       const std::vector<ObstacleBox>& boxes, double since_last_s) {
  if (!give_way_to_.empty()) {
    const auto it = std::find_if(peers.begin(), peers.end(), [&](const Fragment* p) { return p->robot_id == give_way_to_; });
    // Step aside all the way first: released halfway, the robot would stand in the way again.
    const double to_spot = distance_xy(position, give_way_spot_);
    const bool at_spot = to_spot < options_.min_move_m;
    // Driven towards the spot without getting closer (the driver is blocked: the spot, chosen
    // without a map, is out of reach): give it up. Time spent stopped for a teammate does not count.
    if (to_spot < give_way_best_m_ - options_.min_move_m) {
      give_way_best_m_ = to_spot;
      give_way_stalled_s_ = 0.0;
    } else if (give_way_approved_) {
      give_way_stalled_s_ += since_last_s;
    }
    if (it == peers.end() || (at_spot && (*it)->yielding_to != robot_id_)) {
      give_way_to_.clear();
    } else if (!at_spot && give_way_stalled_s_ >= options_.give_way_timeout_s) {
      failed_give_way_dirs_.push_back((give_way_spot_ - position).head<2>().normalized());
      give_way_to_.clear();
      ++counters_.give_ways_abandoned;
    }
  }
  // A standoff is over once nothing blocks this robot: failed directions are forgotten.
  if (give_way_to_.empty() && !detour.blocked) failed_give_way_dirs_.clear();
  if (give_way_to_.empty() && detour.blocked) {
    const auto it = std::find_if(peers.begin(), peers.end(), [&](const Fragment* p) { return p->robot_id == detour.blocked_by; });
    if (it != peers.end() && (*it)->stationary && (*it)->yielding_to == robot_id_ && (*it)->robot_id < robot_id_) {
      if (auto spot = find_room(position, **it, boxes)) {
        give_way_to_ = (*it)->robot_id;
        give_way_spot_ = *spot;
        give_way_best_m_ = distance_xy(position, *spot);
        give_way_stalled_s_ = 0.0;
        ++counters_.give_ways;
      }
    }
  }
}

ConflictResolver::Limit ConflictResolver::yield_limit(const Path& near, const std::vector<const Fragment*>& peers,
                                                     double speed_mps, double now_s) {
  Limit out;
  std::set<std::string> conflicting_now;
  for (const Fragment* p : peers) {
    auto record = yields_.find(p->robot_id);
    if (p->stationary && record == yields_.end()) continue;
    // A stopped robot occupies only its place, whatever it would like to do next.
    Path peer_path = p->stationary ? Path{p->position_m} : p->path();
    // A fragment as long as eta_p was cut there: the peer's path goes on beyond it.
    if (!p->stationary && path_length(peer_path) >= options_.eta_p_m - 0.05) {
      peer_path = extend_path(peer_path, options_.extrapolate_m);
    }
    const double zone = radius_m_ + p->body_radius_m() + options_.conflict_margin_m;
    const auto conflict = find_conflict(near, peer_path, zone, options_.sample_step_m);
    if (!conflict) {
      if (record != yields_.end()) yields_.erase(record);
      continue;
    }
    conflicting_now.insert(p->robot_id);
    if (!conflicting_.count(p->robot_id)) ++counters_.conflicts_detected;

    bool yield = false;
    if (record != yields_.end()) {
      yield = still_yielding(*p, record->second, peers, now_s);
    } else if (p->yielding_to != robot_id_) {
      const double t_own = stationary_ ? kInf : time_to_reach(conflict->own_entry_m, speed_mps);
      const double t_peer = p->stationary ? kInf : time_to_reach(conflict->peer_entry_m, p->speed_mps);
      yield = priority_of(t_peer, p->robot_id, options_.tie_window_s) <
              priority_of(t_own, robot_id_, options_.tie_window_s);
      if (yield) {
        yields_[p->robot_id] = {now_s, conflict->kind};
        record = yields_.find(p->robot_id);
        ++counters_.yields;
      }
    }
    if (!yield) {
      if (record != yields_.end()) yields_.erase(record);
      continue;
    }
    const double stop_at = conflict->own_entry_m - options_.stop_buffer_m;
    if (stop_at < out.limit_s) {
      out.limit_s = stop_at;
      out.yielding_to = p->robot_id;
      out.reason = "yield to " + p->robot_id + " (" + std::string(conflict_kind_name(record->second.kind)) + ")";
    }
  }
  conflicting_ = std::move(conflicting_now);
  return out;
}

bool ConflictResolver::still_yielding(const Fragment& peer, const YieldRecord& record,
                                      const std::vector<const Fragment*>& peers, double now_s) {
  const std::string lowest = lowest_in_wait_cycle(peer.robot_id, peers);
  // A stopped robot that shows a wanted path and waits for this one is blocked by this
  // robot's box: it cannot move first, so this robot must.
  const bool blocked_by_me = peer.stationary && peer.yielding_to == robot_id_ && !peer.waypoints_m.empty();
  if (blocked_by_me) {
    ++counters_.deadlock_breaks;
    return false;
  }
  if (!lowest.empty()) {
    // Waiting in a circle (two robots waiting for each other, or more): the lowest id in
    // the circle goes, the others keep waiting. Every member sees the same circle.
    if (lowest != robot_id_) return true;
    ++counters_.deadlock_breaks;
    return false;
  }
  if (peer.stationary && now_s - record.since_s > options_.deadlock_timeout_s) {
    // The robot waited for has stopped for reasons of its own (blocked elsewhere, scanning,
    // waiting further down a chain): stop waiting and drive around it as an obstacle.
    ++counters_.deadlock_breaks;
    return false;
  }
  return true;
}

const Fragment* ConflictResolver::hold_off(const Eigen::Vector3d& position, const Path& path, double speed_mps,
                                           const std::vector<const Fragment*>& peers, double& limit_s,
                                           std::string& why) const {
  const Fragment* stopped_by = nullptr;
  const auto samples = sample_path(path, options_.sample_step_m * 0.5);
  for (const Fragment* p : peers) {
    const double hard = radius_m_ + p->body_radius_m() + options_.hard_margin_m +
                        (p->stationary ? 0.0 : (speed_mps + p->speed_mps) * options_.cycle_s);
    const double threshold = std::min(hard, p->distance_to(position) - 1e-3);
    for (size_t i = 1; i < samples.size() && samples[i - 1].s_m < limit_s; ++i) {
      if (p->distance_to(samples[i].point) < threshold) {
        limit_s = samples[i - 1].s_m;
        why = "too close to " + p->robot_id;
        stopped_by = p->stationary ? p : nullptr;
        break;
      }
    }
  }
  return stopped_by;
}

std::optional<Path> ConflictResolver::step_out_of(const Eigen::Vector3d& position, const Fragment& held_by) const {
  const Eigen::Vector2d lo = held_by.box_min_m.head<2>().array() - (radius_m_ + options_.obstacle_margin_m);
  const Eigen::Vector2d hi = held_by.box_max_m.head<2>().array() + (radius_m_ + options_.obstacle_margin_m);
  Eigen::Vector2d away = (position - held_by.position_m).head<2>();
  if (away.norm() < 1e-6) away = Eigen::Vector2d::UnitX();
  away.normalize();
  double exit_t = kInf;
  for (int a = 0; a < 2; ++a) {
    if (std::abs(away[a]) < 1e-9) continue;
    const double bound = away[a] > 0 ? hi[a] : lo[a];
    exit_t = std::min(exit_t, (bound - position[a]) / away[a]);
  }
  if (!std::isfinite(exit_t) || exit_t <= 0.0) return std::nullopt;
  const double out = exit_t + options_.detour_clearance_m;
  return Path{position, position + Eigen::Vector3d(away.x() * out, away.y() * out, 0.0)};
}

Decision ConflictResolver::decide(const Eigen::Vector3d& position, const Path& desired_path, double speed_mps,
                                  const std::vector<Fragment>& peers_in, double now_s) {
  const double since_last_s = std::max(0.0, now_s - last_decide_s_);
  last_decide_s_ = now_s;
  const std::vector<Fragment> adjusted = with_frozen_as_stopped(peers_in, now_s);
  const Path remaining = remaining_desired(position, desired_path, speed_mps);
  // Only teammates on this robot's storey take part (see on_another_level).
  const Path near = truncate_to_length(remaining, options_.eta_p_m + options_.extrapolate_m);
  std::vector<const Fragment*> peers;
  for (const auto& p : adjusted)
    if (!on_another_level(near, p)) peers.push_back(&p);
  std::sort(peers.begin(), peers.end(), [](const Fragment* a, const Fragment* b) { return a->robot_id < b->robot_id; });
  // Yields to robots that are no longer heard from (or have left this storey) end with them.
  for (auto it = yields_.begin(); it != yields_.end();) {
    const bool present = std::any_of(peers.begin(), peers.end(), [&](const Fragment* p) { return p->robot_id == it->first; });
    it = present ? std::next(it) : yields_.erase(it);
  }

  if (desired_path.empty() || path_length(remaining) < options_.min_move_m || !(speed_mps > 0.0)) {
    yields_.clear();
    conflicting_.clear();
    was_detoured_ = false;
    give_way_approved_ = false;
    return stop(desired_path.empty() ? "no path" : "at goal", "");
  }

  // Obstacle avoidance: every stationary teammate is a box to drive around.
  std::vector<ObstacleBox> boxes;
  for (const Fragment* p : peers) {
    if (!p->stationary) continue;
    const double grow = radius_m_ + options_.obstacle_margin_m;
    boxes.push_back({p->robot_id, p->box_min_m.head<2>().array() - grow, p->box_max_m.head<2>().array() + grow});
  }
  const DetourResult detour = detour_stopped(position, desired_path, remaining, boxes);
  Path candidate = detour.path;

  // Two robots standing in each other's way (each blocked by the other's box, e.g. each on the
  // other's goal): the higher id makes room by stepping aside off the other's wanted path.
  update_give_way(position, detour, peers, boxes, since_last_s);
  const std::string giving_way_to = give_way_to_;
  if (!giving_way_to.empty()) {
    candidate = {position, give_way_spot_};
    wanted_near_.clear();
  }

  // Collision avoidance against moving teammates (and stopped ones this robot still waits for).
  Limit limit = yield_limit(truncate_to_length(candidate, options_.eta_p_m + options_.extrapolate_m), peers,
                            speed_mps, now_s);

  // Last line of defence against inconsistent views (see hold_off).
  const double limit_before = limit.limit_s;
  const Fragment* held_by = hold_off(position, candidate, speed_mps, peers, limit.limit_s, limit.reason);
  if (held_by != nullptr && limit.limit_s < options_.min_move_m) {
    // Held off inside a stopped teammate's box, so the detour cannot go round it: step out of
    // the box straight away from its body first; the next decisions go round it.
    if (const auto step_out = step_out_of(position, *held_by)) {
      double step_limit = limit_before;
      std::string step_reason;
      hold_off(position, *step_out, speed_mps, peers, step_limit, step_reason);
      if (!std::isfinite(step_limit) || step_limit >= options_.min_move_m) {
        candidate = *step_out;
        limit.limit_s = step_limit;
        limit.reason = step_reason.empty() ? "stepping out of " + held_by->robot_id + "'s way" : step_reason;
      }
    }
  }
  return finish(candidate, limit, giving_way_to, detour, speed_mps);
}

Decision ConflictResolver::finish(const Path& candidate, Limit limit, const std::string& giving_way_to,
                                  const DetourResult& detour, double speed_mps) {
  Path approved = std::isfinite(limit.limit_s) ? truncate_to_length(candidate, limit.limit_s) : candidate;
  std::string reason = std::move(limit.reason);
  std::string yielding_to = std::move(limit.yielding_to);
  if (reason.empty() && !giving_way_to.empty()) {
    reason = "giving way to " + giving_way_to;
    yielding_to = giving_way_to;
  }
  if (reason.empty() && detour.blocked) {
    reason = "blocked by stationary robot " + detour.blocked_by;
    yielding_to = detour.blocked_by;  // waits for it: lets wait cycles be seen by everyone
  }
  give_way_approved_ = !giving_way_to.empty() && path_length(approved) >= options_.min_move_m;
  if (path_length(approved) < options_.min_move_m) {
    if (reason.empty()) reason = "no room to move";
    Decision d = stop(std::move(reason), yielding_to);
    d.detoured = detour.detoured;
    last_ = d;
    return d;
  }
  Decision d;
  d.kind = DecisionKind::kFollow;
  d.waypoints = std::move(approved);
  d.speed_mps = speed_mps;
  d.reason = std::move(reason);
  d.yielding_to = std::move(yielding_to);
  d.detoured = detour.detoured;
  stationary_ = false;
  last_ = d;
  return d;
}

Fragment ConflictResolver::fragment(const Eigen::Vector3d& position) const {
  Fragment f;
  f.robot_id = robot_id_;
  f.position_m = position;
  f.stationary = last_.kind == DecisionKind::kStop;
  f.speed_mps = f.stationary ? 0.0 : last_.speed_mps;
  // Moving: the approved path ahead. Stopped and blocked: the path it is waiting to drive.
  const Path near = f.stationary ? wanted_near_ : truncate_to_length(remaining_path(position, last_.waypoints), options_.eta_p_m);
  if (!near.empty()) f.waypoints_m.assign(near.begin() + 1, near.end());
  body_box_any_yaw(position, half_extents_m_, f.box_min_m, f.box_max_m);
  f.yielding_to = last_.yielding_to;
  return f;
}

}  // namespace hexplore::safety
