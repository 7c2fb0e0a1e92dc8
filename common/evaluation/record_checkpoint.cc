#include "common/evaluation/record_checkpoint.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "common/evaluation/team_recorder.h"

namespace hexplore::evaluation {
namespace {

// Raised when a field changes meaning; a checkpoint of another format is not resumed.
constexpr uint32_t kFormat = 1;

template <typename Map>
void copy_map(const Map& from, google::protobuf::Map<std::string, typename Map::mapped_type>* to) {
  for (const auto& [key, value] : from) (*to)[key] = value;
}

template <typename Value>
std::map<std::string, Value> to_std_map(const google::protobuf::Map<std::string, Value>& from) {
  return {from.begin(), from.end()};
}

std::string joined(const std::set<std::string>& ids) {
  std::string out;
  for (const auto& id : ids) out += (out.empty() ? "" : ", ") + id;
  return out.empty() ? "(none)" : out;
}

}  // namespace

v1::StationCheckpoint TeamRecorder::checkpoint() const {
  v1::StationCheckpoint c;
  c.set_format(kFormat);
  c.set_scene(record_.scene);
  c.set_planner(record_.planner);
  c.set_mode(record_.mode);
  c.set_seed(record_.seed);
  c.set_start_sim_time_s(start_s_.value_or(0.0));
  c.set_latest_sim_time_s(latest_sim_time_s_);
  c.set_station_restarts(record_.station_restarts);
  c.set_unrecorded_s(record_.station_unrecorded_s);
  for (const CompletenessSample& s : record_.completeness) {
    auto* out = c.add_completeness();
    out->set_sim_time_s(s.sim_time_s);
    out->set_team(s.team);
    out->set_team_observable(s.team_observable);
    copy_map(s.per_robot, out->mutable_per_robot());
  }
  for (const auto& [id, track] : record_.robots) {
    auto* out = c.add_robots();
    out->set_robot(id);
    for (size_t i = 0; i < track.positions_m.size(); ++i) {
      out->add_times_s(i < track.times_s.size() ? track.times_s[i] : 0.0);
      for (int k = 0; k < 3; ++k) out->add_positions_m(track.positions_m[i][k]);
      const Eigen::Quaterniond q = i < track.orientations.size() ? track.orientations[i] : Eigen::Quaterniond::Identity();
      for (double v : {q.w(), q.x(), q.y(), q.z()}) out->add_orientations(v);
    }
    out->set_length_m(track.length_m);
    out->set_collisions(track.collisions);
    out->set_last_state(track.last_state);
    copy_map(track.counters, out->mutable_counters());
    out->set_own_increment_seq(track.own_increment_seq);
    copy_map(track.synced_seq, out->mutable_synced_seq());
    for (const auto& [peer, stretches] : track.unsynced) {
      auto* kept = out->add_unsynced();
      kept->set_peer(peer);
      for (const auto& [from, to] : stretches) {
        kept->add_from_to_s(from);
        kept->add_from_to_s(to);
      }
    }
    out->set_longest_blocked_s(track.longest_blocked_s);
    out->set_blocked_since_s(track.blocked_since_s);
    if (auto it = record_.planning_times_s.find(id); it != record_.planning_times_s.end())
      for (double t : it->second) out->add_planning_times_s(t);
    if (auto it = record_.team_bytes.find(id); it != record_.team_bytes.end()) copy_map(it->second, out->mutable_team_bytes());
    if (auto it = record_.team_messages.find(id); it != record_.team_messages.end())
      copy_map(it->second, out->mutable_team_messages());
    if (auto it = last_round_.find(id); it != last_round_.end()) {
      out->set_has_last_round(true);
      out->set_last_round(it->second);
    }
    if (auto it = chord_length_m_.find(id); it != chord_length_m_.end()) out->set_chord_length_m(it->second);
    if (auto it = counters_.find(id); it != counters_.end())
      for (const auto& [key, counter] : it->second) {
        auto* kept = out->add_status_counters();
        kept->set_key(key);
        kept->set_at_start(counter.at_start);
        kept->set_latest(counter.latest);
        kept->set_seen(counter.seen);
      }
  }
  for (const OpenTargetRow& row : record_.open_targets) {
    auto* out = c.add_open_targets();
    out->set_sim_time_s(row.sim_time_s);
    out->set_robot(row.robot);
    out->set_key(row.key);
    out->set_x_m(row.center.x());
    out->set_y_m(row.center.y());
    out->set_z_m(row.center.z());
    out->set_facade(row.facade);
    out->set_voxels(row.voxels);
    out->set_covered_voxels(row.covered_voxels);
    out->set_gap(row.gap);
    out->set_state(row.state);
    out->set_attempts(row.attempts);
  }
  return c;
}

void TeamRecorder::resume(const v1::StationCheckpoint& c, double now_sim_time_s) {
  start_s_ = c.start_sim_time_s();
  latest_sim_time_s_ = std::max(latest_sim_time_s_, now_sim_time_s);
  record_.station_restarts = c.station_restarts() + 1;
  record_.station_unrecorded_s = c.unrecorded_s() + std::max(0.0, now_sim_time_s - c.latest_sim_time_s());
  record_.completeness.clear();
  for (const auto& s : c.completeness())
    record_.completeness.push_back({s.sim_time_s(), s.team(), s.team_observable(), to_std_map(s.per_robot())});
  for (const auto& in : c.robots()) {
    auto it = record_.robots.find(in.robot());
    if (it == record_.robots.end()) continue;  // checkpoint_mismatch() refuses other rosters
    RobotTrack& track = it->second;
    const size_t samples = size_t(in.times_s_size());
    track.times_s.assign(in.times_s().begin(), in.times_s().end());
    track.positions_m.clear();
    track.orientations.clear();
    for (size_t i = 0; i < samples && 3 * i + 2 < size_t(in.positions_m_size()); ++i)
      track.positions_m.emplace_back(in.positions_m(3 * i), in.positions_m(3 * i + 1), in.positions_m(3 * i + 2));
    for (size_t i = 0; i < samples && 4 * i + 3 < size_t(in.orientations_size()); ++i)
      track.orientations.emplace_back(in.orientations(4 * i), in.orientations(4 * i + 1), in.orientations(4 * i + 2),
                                      in.orientations(4 * i + 3));
    track.times_s.resize(track.positions_m.size());
    track.length_m = in.length_m();
    track.collisions = in.collisions();
    track.last_state = in.last_state();
    track.counters = to_std_map(in.counters());
    track.own_increment_seq = in.own_increment_seq();
    track.synced_seq = to_std_map(in.synced_seq());
    track.unsynced.clear();
    for (const auto& kept : in.unsynced()) {
      auto& stretches = track.unsynced[kept.peer()];
      for (int i = 0; i + 1 < kept.from_to_s_size(); i += 2) stretches.emplace_back(kept.from_to_s(i), kept.from_to_s(i + 1));
    }
    track.longest_blocked_s = in.longest_blocked_s();
    // The stretch a robot was BLOCKED in when the station went down is not known to go on.
    track.blocked_since_s = -1.0;
    record_.planning_times_s[in.robot()].assign(in.planning_times_s().begin(), in.planning_times_s().end());
    record_.team_bytes[in.robot()] = to_std_map(in.team_bytes());
    record_.team_messages[in.robot()] = to_std_map(in.team_messages());
    if (in.has_last_round()) last_round_[in.robot()] = in.last_round();
    chord_length_m_[in.robot()] = in.chord_length_m();
    for (const auto& kept : in.status_counters())
      counters_[in.robot()][kept.key()] = Counter{kept.at_start(), kept.latest(), kept.seen()};
  }
  record_.open_targets.clear();
  for (const auto& in : c.open_targets()) {
    OpenTargetRow row;
    row.sim_time_s = in.sim_time_s();
    row.robot = in.robot();
    row.key = in.key();
    row.center = {in.x_m(), in.y_m(), in.z_m()};
    row.facade = in.facade();
    row.voxels = in.voxels();
    row.covered_voxels = in.covered_voxels();
    row.gap = in.gap();
    row.state = in.state();
    row.attempts = in.attempts();
    record_.open_targets.push_back(std::move(row));
  }
}

void save_checkpoint(const v1::StationCheckpoint& checkpoint, const std::string& path) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw CheckpointError("station checkpoint: cannot open '" + tmp + "' for writing");
    if (!checkpoint.SerializeToOstream(&out)) throw CheckpointError("station checkpoint: write to '" + tmp + "' failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw CheckpointError("station checkpoint: cannot rename '" + tmp + "' to '" + path + "'");
}

std::optional<v1::StationCheckpoint> load_checkpoint(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError("station checkpoint '" + path + "': cannot open for reading");
  v1::StationCheckpoint checkpoint;
  if (!checkpoint.ParseFromIstream(&in)) throw CheckpointError("station checkpoint '" + path + "': not a checkpoint (parse failed)");
  if (checkpoint.format() != kFormat)
    throw CheckpointError("station checkpoint '" + path + "': format " + std::to_string(checkpoint.format()) +
                          ", this station reads format " + std::to_string(kFormat));
  return checkpoint;
}

std::string checkpoint_mismatch(const v1::StationCheckpoint& checkpoint, const core::TeamConfig& team) {
  if (checkpoint.scene() != team.scene) return "its scene is '" + checkpoint.scene() + "', the team's '" + team.scene + "'";
  if (checkpoint.seed() != team.params.seed)
    return "its seed is " + std::to_string(checkpoint.seed()) + ", the team's " + std::to_string(team.params.seed);
  std::set<std::string> recorded, roster;
  for (const auto& track : checkpoint.robots()) recorded.insert(track.robot());
  for (const auto& robot : team.robots) roster.insert(robot.id);
  if (recorded != roster) return "it records robots " + joined(recorded) + ", the team has " + joined(roster);
  return "";
}

}  // namespace hexplore::evaluation
