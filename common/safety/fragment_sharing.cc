#include "common/safety/fragment_sharing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hexplore::safety {
namespace {

constexpr double kCutSlackM = 0.05;  // as the resolver: a fragment this close to eta_p was cut
constexpr double kCompareStepM = 0.25;

// The part of `path` from arc length `s_m` on, starting at the point there.
Path sub_path(const Path& path, double s_m) {
  Path out{point_at(path, s_m)};
  double travelled = 0.0;
  for (size_t i = 1; i < path.size(); ++i) {
    travelled += distance_xy(path[i - 1], path[i]);
    if (travelled > s_m + 1e-9) out.push_back(path[i]);
  }
  return out;
}

bool is_cut(const Path& path, double eta_p_m) { return path_length(path) >= eta_p_m - kCutSlackM; }

}  // namespace

void SharingOptions::validate() const {
  auto fail = [](const std::string& field, const std::string& problem) {
    throw std::invalid_argument("safety: SharingOptions." + field + " " + problem);
  };
  if (!(heartbeat_s > 0.0)) fail("heartbeat_s", "must be > 0");
  if (!(repeat_after_s >= 0.0)) fail("repeat_after_s", "must be >= 0");
  if (!(tolerance_m > 0.0)) fail("tolerance_m", "must be > 0");
  if (!(speed_tolerance_mps >= 0.0)) fail("speed_tolerance_mps", "must be >= 0");
  if (!(eta_p_m > 0.0)) fail("eta_p_m", "must be > 0");
}

Fragment advance_fragment(const Fragment& f, double age_s, double eta_p_m) {
  if (f.stationary || !(f.speed_mps > 0.0) || !(age_s > 0.0)) return f;
  Path path = f.path();
  const double length = path_length(path);
  double travel = f.speed_mps * age_s;
  if (is_cut(path, eta_p_m)) {
    path = extend_path(path, travel);
  } else {
    travel = std::min(travel, length);
  }
  const Path ahead = sub_path(path, travel);
  Fragment out = f;
  out.position_m = ahead.front();
  out.waypoints_m.assign(ahead.begin() + 1, ahead.end());
  // Behind the prediction: where it was reported, up to where it is believed to be.
  out.trail_m = truncate_to_length(path, travel);
  const Eigen::Vector3d moved = out.position_m - f.position_m;
  out.box_min_m += moved;
  out.box_max_m += moved;
  return out;
}

FragmentSchedule::FragmentSchedule(SharingOptions options) : options_(options) { options_.validate(); }

bool FragmentSchedule::due(double now_s, const Fragment& current) const {
  if (!last_) return true;
  const double age = now_s - last_s_;
  if (age >= options_.heartbeat_s || age < 0.0) return true;
  if (repeat_ && age >= options_.repeat_after_s) return true;
  return changed(now_s, current);
}

bool FragmentSchedule::changed(double now_s, const Fragment& current) const {
  const double age = now_s - last_s_;
  if (current.stationary != last_->stationary || current.yielding_to != last_->yielding_to) return true;
  if (std::abs(current.speed_mps - last_->speed_mps) > options_.speed_tolerance_mps) return true;
  // What teammates believe now, against what the robot would share now: same place, same way
  // ahead (compared at equal distances along both), same end.
  const Fragment predicted = advance_fragment(*last_, age, options_.eta_p_m);
  const Path believed = predicted.path();
  const Path actual = current.path();
  const double actual_length = path_length(actual);
  if (std::abs(path_length(believed) - actual_length) > options_.tolerance_m) return true;
  for (double s = 0.0;; s += kCompareStepM) {
    const double at = std::min(s, actual_length);
    if (distance_xy(point_at(believed, at), point_at(actual, at)) > options_.tolerance_m) return true;
    if (at >= actual_length) break;
  }
  return false;
}

void FragmentSchedule::sent(double now_s, const Fragment& fragment) {
  // A change is repeated once; the repeat itself (nothing changed since) and heartbeats are not.
  repeat_ = last_ && now_s - last_s_ < options_.heartbeat_s && changed(now_s, fragment);
  last_ = fragment;
  last_s_ = now_s;
}

}  // namespace hexplore::safety
