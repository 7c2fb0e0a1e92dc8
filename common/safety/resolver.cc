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
  conflicting_.clear();
  stationary_ = true;
  was_detoured_ = false;
  last_ = Decision{};
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

Decision ConflictResolver::decide(const Eigen::Vector3d& position, const Path& desired_path, double speed_mps,
                                  const std::vector<Fragment>& peers_in, double now_s) {
  std::vector<const Fragment*> peers;
  for (const auto& p : peers_in) {
    if (p.robot_id != robot_id_) peers.push_back(&p);
  }
  std::sort(peers.begin(), peers.end(), [](const Fragment* a, const Fragment* b) { return a->robot_id < b->robot_id; });
  // Yields to robots that are no longer heard from end with them.
  for (auto it = yields_.begin(); it != yields_.end();) {
    const bool present = std::any_of(peers.begin(), peers.end(), [&](const Fragment* p) { return p->robot_id == it->first; });
    it = present ? std::next(it) : yields_.erase(it);
  }

  const Path remaining = remaining_path(position, desired_path);
  if (desired_path.empty() || path_length(remaining) < options_.min_move_m || !(speed_mps > 0.0)) {
    yields_.clear();
    conflicting_.clear();
    was_detoured_ = false;
    return stop(desired_path.empty() ? "no path" : "at goal", "");
  }

  // Obstacle avoidance: every stationary teammate is a box to drive around.
  std::vector<ObstacleBox> boxes;
  for (const Fragment* p : peers) {
    if (!p->stationary) continue;
    const double grow = radius_m_ + options_.obstacle_margin_m;
    boxes.push_back({p->robot_id, p->box_min_m.head<2>().array() - grow, p->box_max_m.head<2>().array() + grow});
  }
  DetourOptions detour_options;
  detour_options.clearance_m = options_.detour_clearance_m;
  // Once on a detour, keep following it while the plan and the obstacles last: re-deriving it
  // from the plan every cycle would pull the robot back towards the box and make it dither.
  const bool keep_detour = was_detoured_ && !boxes.empty() && desired_path == detour_for_;
  const Path base = keep_detour ? remaining_path(position, detour_path_) : remaining_path(position, desired_path);
  DetourResult detour = detour_around(base, boxes, detour_options);
  if (detour.detoured && !keep_detour) ++counters_.detours;
  detour.detoured = detour.detoured || keep_detour;
  was_detoured_ = detour.detoured && !detour.blocked;
  if (was_detoured_) {
    detour_path_ = detour.path;
    detour_for_ = desired_path;
  }
  const Path& candidate = detour.path;
  if (detour.blocked) ++counters_.blocked;

  // Collision avoidance against moving teammates (and stopped ones this robot still waits for).
  const Path near = truncate_to_length(candidate, options_.eta_p_m + options_.extrapolate_m);
  double limit_s = kInf;
  std::string limit_reason;
  std::string yielding_to;
  std::set<std::string> conflicting_now;
  for (const Fragment* p : peers) {
    auto record = yields_.find(p->robot_id);
    if (p->stationary && record == yields_.end()) continue;
    Path peer_path = p->path();
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
      yield = true;
      if (p->yielding_to == robot_id_) {
        // Both wait for each other: the lower id goes, the other keeps waiting.
        if (robot_id_ < p->robot_id) {
          yield = false;
          ++counters_.deadlock_breaks;
        }
      } else if (p->stationary && p->yielding_to.empty() && now_s - record->second.since_s > options_.deadlock_timeout_s) {
        // The robot waited for has stopped for good reasons of its own (blocked, scanning):
        // stop waiting and drive around it as an obstacle.
        yield = false;
        ++counters_.deadlock_breaks;
      }
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
    if (stop_at < limit_s) {
      limit_s = stop_at;
      yielding_to = p->robot_id;
      limit_reason = "yield to " + p->robot_id + " (" + std::string(conflict_kind_name(record->second.kind)) + ")";
    }
  }
  conflicting_ = std::move(conflicting_now);

  // Last line of defence against inconsistent views: never close in on a moving teammate's
  // body beyond the hard distance (or beyond the current distance when already inside it).
  const auto samples = sample_path(candidate, options_.sample_step_m * 0.5);
  for (const Fragment* p : peers) {
    if (p->stationary) continue;
    const double hard = radius_m_ + p->body_radius_m() + options_.hard_margin_m +
                        (speed_mps + p->speed_mps) * options_.cycle_s;
    const double threshold = std::min(hard, distance_xy(position, p->position_m) - 1e-3);
    for (size_t i = 1; i < samples.size() && samples[i - 1].s_m < limit_s; ++i) {
      if (distance_xy(samples[i].point, p->position_m) < threshold) {
        if (samples[i - 1].s_m < limit_s) {
          limit_s = samples[i - 1].s_m;
          limit_reason = "too close to " + p->robot_id;
        }
        break;
      }
    }
  }

  Path approved = std::isfinite(limit_s) ? truncate_to_length(candidate, limit_s) : candidate;
  std::string reason = limit_reason;
  if (reason.empty() && detour.blocked) reason = "blocked by stationary robot " + detour.blocked_by;
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
  if (!f.stationary) {
    const Path near = truncate_to_length(remaining_path(position, last_.waypoints), options_.eta_p_m);
    f.waypoints_m.assign(near.begin() + (near.size() > 1 ? 1 : 0), near.end());
  }
  body_box_any_yaw(position, half_extents_m_, f.box_min_m, f.box_max_m);
  f.yielding_to = last_.yielding_to;
  return f;
}

}  // namespace hexplore::safety
