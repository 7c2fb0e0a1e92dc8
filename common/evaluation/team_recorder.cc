#include "common/evaluation/team_recorder.h"

#include <algorithm>

namespace hexplore::evaluation {
namespace {

// Trajectory points closer than this (in time and space) to the previous one are not stored;
// lengths are still accumulated from every pose.
constexpr double kMinSampleSpacingM = 0.25;
constexpr double kMinSamplePeriodS = 2.0;

std::optional<double> status_value(const v1::ServiceStatus& status, std::string_view name) {
  for (const auto& v : status.values())
    if (v.name() == name) return v.value();
  return std::nullopt;
}

}  // namespace

const std::vector<std::string>& status_counters() {
  static const std::vector<std::string> kCounters = {
      "sim.odometry_m",          "sim.collisions",          "hlmap.gaps_detected",   "hlmap.gaps_repaired",
      "hlmap.repair_requests",   "hlmap.snapshots_applied", "hlmap.peer_restarts",   "hlmap.full_map_bytes",
      "hlmap.digests_checked",   "hlmap.digest_mismatches",
      "mapping.raw_map_bytes",
      "*.radio_expired",         "*.radio_lost",            "*.radio_out_of_range"};
  return kCounters;
}

std::optional<std::string> communication_category(std::string_view topic) {
  if (topic == "team/pose") return "pose";
  if (topic == "team/map") return "incremental_map";
  if (topic == "team/path") return "executable_path";
  if (topic == "team/plan") return "exploration_route";
  return std::nullopt;
}

TeamRecorder::TeamRecorder(const core::TeamConfig& team) : team_(&team) {
  record_.scene = team.scene;
  record_.planner = team.params.planner;
  record_.seed = team.params.seed;
  record_.planner_seed = team.params.planner_seed;
  for (const auto& robot : team.robots) record_.robots[robot.id].species = robot.species;
}

void TeamRecorder::start(double sim_time_s) {
  start_s_ = sim_time_s;
  latest_sim_time_s_ = std::max(latest_sim_time_s_, sim_time_s);
  for (auto& [_, track] : record_.robots) {
    track.times_s.clear();
    track.positions_m.clear();
    track.orientations.clear();
    track.length_m = 0.0;
    track.longest_blocked_s = 0.0;
    track.blocked_since_s = -1.0;
    track.unsynced.clear();
  }
  chord_length_m_.clear();
  for (auto& [robot, counters] : counters_)
    for (auto& [key, c] : counters) {
      c.at_start = c.seen ? c.latest : 0.0;
      record_.robots[robot].counters[key] = 0.0;
    }
  for (auto& [_, categories] : record_.team_bytes) categories.clear();
  for (auto& [_, categories] : record_.team_messages) categories.clear();
  record_.completeness.clear();
  record_.planning_times_s.clear();
}

double TeamRecorder::mission_time_s() const {
  return start_s_ ? std::max(0.0, latest_sim_time_s_ - *start_s_) : 0.0;
}

bool TeamRecorder::on_pose(const std::string& robot, double sim_time_s, const v1::RobotPose& pose) {
  auto it = record_.robots.find(robot);
  if (it == record_.robots.end()) return false;
  latest_sim_time_s_ = std::max(latest_sim_time_s_, sim_time_s);
  auto& track = it->second;
  track.last_state = v1::MotionState_Name(pose.state());
  if (!start_s_) return true;
  const Eigen::Vector3d p(pose.pose().position_m().x(), pose.pose().position_m().y(), pose.pose().position_m().z());
  if (!p.allFinite()) return false;
  const double t = sim_time_s - *start_s_;
  if (pose.state() == v1::MOTION_STATE_BLOCKED) {
    if (track.blocked_since_s < 0.0) track.blocked_since_s = t;
    track.longest_blocked_s = std::max(track.longest_blocked_s, t - track.blocked_since_s);
  } else {
    track.blocked_since_s = -1.0;
  }
  const auto& o = pose.pose().orientation();
  Eigen::Quaterniond q(o.w(), o.x(), o.y(), o.z());
  q = q.norm() > 1e-9 && q.coeffs().allFinite() ? q.normalized() : Eigen::Quaterniond::Identity();
  if (track.positions_m.empty()) {
    track.positions_m.push_back(p);
    track.orientations.push_back(q);
    track.times_s.push_back(t);
    return true;
  }
  const double step = (p - track.positions_m.back()).norm();
  if (step >= kMinSampleSpacingM || t - track.times_s.back() >= kMinSamplePeriodS) {
    chord_length_m_[robot] += step;
    track.positions_m.push_back(p);
    track.orientations.push_back(q);
    track.times_s.push_back(t);
  }
  // The sim integrates odometry every motion step (its status); the chord sum of the poses
  // heard is the fallback for drivers that do not report it.
  if (!counters_[robot]["sim.odometry_m"].seen) track.length_m = chord_length_m_[robot];
  return true;
}

void TeamRecorder::on_team_message(const std::string& robot, std::string_view topic, size_t bytes) {
  if (!start_s_ || !record_.robots.contains(robot)) return;
  if (const auto category = communication_category(topic)) {
    record_.team_bytes[robot][*category] += bytes;
    ++record_.team_messages[robot][*category];
  }
}

void TeamRecorder::on_status(const std::string& robot, std::string_view service, const v1::ServiceStatus& status) {
  auto track = record_.robots.find(robot);
  if (track == record_.robots.end()) return;
  const auto& known = status_counters();
  auto kept = [&](const std::string& key, const std::string& value) {
    // "*.value": any service's (the radio drops each service counts for its own sockets).
    return std::find(known.begin(), known.end(), key) != known.end() ||
           std::find(known.begin(), known.end(), "*." + value) != known.end();
  };
  for (const auto& v : status.values()) {
    if (service == "hlmap" && record_map_sync(track->second, v.name(), v.value())) continue;
    const std::string key = std::string(service) + "." + v.name();
    if (!kept(key, v.name())) continue;
    Counter& c = counters_[robot][key];
    c.latest = v.value();
    c.seen = true;
    if (!start_s_) continue;
    track->second.counters[key] = c.latest - c.at_start;
  }
  const auto& counters = track->second.counters;
  if (auto odometry = counters.find("sim.odometry_m"); odometry != counters.end()) track->second.length_m = odometry->second;
  if (auto collisions = counters_[robot].find("sim.collisions"); collisions != counters_[robot].end())
    track->second.collisions = static_cast<uint32_t>(collisions->second.latest);
}

bool TeamRecorder::record_map_sync(RobotTrack& track, const std::string& name, double value) {
  static const std::string kSynced = "synced_seq.";
  static const std::string kInSync = "in_sync.";
  if (name == "own_increment_seq") {
    track.own_increment_seq = value;
    return true;
  }
  if (name.rfind(kInSync, 0) == 0) {
    const std::string source = name.substr(kInSync.size());
    if (!start_s_ || !record_.robots.contains(source)) return true;
    auto& stretches = track.unsynced[source];
    const bool open = !stretches.empty() && stretches.back().second < 0;
    const double t = mission_time_s();
    if (value == 0.0 && !open) stretches.emplace_back(t, -1.0);
    if (value != 0.0 && open) stretches.back().second = t;
    return true;
  }
  if (name.rfind(kSynced, 0) != 0) return false;
  const std::string source = name.substr(kSynced.size());
  if (record_.robots.contains(source)) track.synced_seq[source] = value;  // an unknown robot is not recorded
  return true;
}

int TeamRecorder::on_planning_status(const std::string& robot, const v1::ServiceStatus& status) {
  const auto round = status_value(status, kPlanningRound);
  const auto time = status_value(status, kPlanningTime);
  if (start_s_ && round && time && record_.robots.contains(robot)) {
    auto last = last_round_.find(robot);
    if (last == last_round_.end() || *round > last->second) {
      record_.planning_times_s[robot].push_back(*time);
      last_round_[robot] = *round;
    }
  }
  const auto views = status_value(status, kViewsRemaining);
  return views ? static_cast<int>(*views) : -1;
}

void TeamRecorder::on_completeness(CompletenessSample sample) {
  if (!start_s_) return;
  record_.completeness.push_back(std::move(sample));
}

}  // namespace hexplore::evaluation
