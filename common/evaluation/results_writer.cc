#include "common/evaluation/results_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "common/evaluation/communication_report.h"
#include "common/evaluation/map_export.h"

namespace hexplore::evaluation {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean(v);
  double sq = 0.0;
  for (double x : v) sq += (x - m) * (x - m);
  return std::sqrt(sq / static_cast<double>(v.size() - 1));
}

std::vector<double> all_planning_times(const ExperimentRecord& r) {
  std::vector<double> all;
  for (const auto& [_, times] : r.planning_times_s) all.insert(all.end(), times.begin(), times.end());
  return all;
}

uint64_t team_bytes_total(const ExperimentRecord& r) {
  uint64_t total = 0;
  for (const auto& [_, categories] : r.team_bytes)
    for (const auto& [__, bytes] : categories) total += bytes;
  return total;
}

void write_text(const std::filesystem::path& path, const std::string& text, std::vector<std::string>& written) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": write failed");
  written.push_back(path.string());
}

// Per robot: how many targets were open at the end, by state and by coverage gap.
std::string open_targets_json(const ExperimentRecord& r) {
  std::map<std::string, std::map<std::string, int>> by_state, by_gap;
  std::map<std::string, int> total;
  for (const auto& t : r.latest_open_targets()) {
    ++total[t.robot];
    ++by_state[t.robot][t.state];
    ++by_gap[t.robot][t.gap];
  }
  auto object = [](const std::map<std::string, int>& m) {
    std::string o = "{";
    for (const auto& [k, v] : m) o += (o.size() > 1 ? ", " : "") + quoted(k) + ": " + std::to_string(v);
    return o + "}";
  };
  std::string j = "{";
  for (const auto& [robot, n] : total)
    j += std::string(j.size() > 1 ? ", " : "") + quoted(robot) + ": {\"total\": " + std::to_string(n) +
         ", \"by_state\": " + object(by_state[robot]) + ", \"by_gap\": " + object(by_gap[robot]) + "}";
  return j + "}";
}

}  // namespace

std::string summary_json(const ExperimentRecord& r) {
  const double duration = std::max(r.exploration_time_s, 1e-9);
  std::ostringstream j;
  j << "{\n";
  j << "  \"scene\": " << quoted(r.scene) << ",\n";
  j << "  \"planner\": " << quoted(r.planner) << ",\n";
  j << "  \"mode\": " << quoted(r.mode) << ",\n";
  j << "  \"seed\": " << r.seed << ",\n";
  j << "  \"planner_seed\": " << r.planner_seed << ",\n";
  j << "  \"end_reason\": " << quoted(r.end_reason) << ",\n";
  j << "  \"exploration_time_s\": " << number(r.exploration_time_s) << ",\n";
  j << "  \"wall_time_s\": " << number(r.wall_time_s) << ",\n";
  j << "  \"station\": {\"restarts\": " << r.station_restarts << ", \"unrecorded_s\": " << number(r.station_unrecorded_s)
    << "},\n";
  j << "  \"final_completeness\": " << number(r.final_team_completeness()) << ",\n";
  j << "  \"final_observable_completeness\": "
    << number(r.completeness.empty() ? 0.0 : r.completeness.back().team_observable) << ",\n";
  j << "  \"accumulated_completeness\": " << number(r.accumulated_completeness()) << ",\n";
  const auto planning = all_planning_times(r);
  j << "  \"planning_time_s\": {\"mean\": " << number(mean(planning)) << ", \"max\": "
    << number(planning.empty() ? 0.0 : *std::max_element(planning.begin(), planning.end()))
    << ", \"rounds\": " << planning.size() << "},\n";
  j << "  \"team_kb_per_s\": " << number(static_cast<double>(team_bytes_total(r)) / 1024.0 / duration) << ",\n";
  j << "  \"map_transmission\": " << map_transmission_json(r) << ",\n";
  j << "  \"open_targets\": " << open_targets_json(r) << ",\n";
  j << "  \"robots\": {";
  bool first = true;
  for (const auto& [id, track] : r.robots) {
    j << (first ? "\n" : ",\n") << "    " << quoted(id) << ": {\"species\": " << quoted(track.species)
      << ", \"trajectory_length_m\": " << number(track.length_m) << ", \"collisions\": " << track.collisions
      << ", \"longest_blocked_s\": " << number(track.longest_blocked_s)
      << ", \"final_completeness\": "
      << number(r.completeness.empty() || !r.completeness.back().per_robot.contains(id)
                    ? 0.0
                    : r.completeness.back().per_robot.at(id))
      << ", \"communication_kb\": {";
    bool first_category = true;
    for (const auto& category : communication_categories()) {
      uint64_t bytes = 0;
      if (auto it = r.team_bytes.find(id); it != r.team_bytes.end())
        if (auto c = it->second.find(category); c != it->second.end()) bytes = c->second;
      j << (first_category ? "" : ", ") << quoted(category) << ": " << number(static_cast<double>(bytes) / 1024.0);
      first_category = false;
    }
    j << "}, " << robot_communication_json(r, id) << "}";
    first = false;
  }
  j << "\n  }\n}\n";
  return j.str();
}

std::vector<std::string> write_results(const ExperimentRecord& r, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create results folder: " + ec.message());
  std::vector<std::string> written;
  const fs::path root(dir);
  write_text(root / "summary.json", summary_json(r), written);

  std::ostringstream c;
  c << "sim_time_s,team,team_observable";
  for (const auto& [id, _] : r.robots) c << "," << id;
  c << "\n";
  for (const auto& s : r.completeness) {
    c << number(s.sim_time_s) << "," << number(s.team) << "," << number(s.team_observable);
    for (const auto& [id, _] : r.robots) c << "," << number(s.per_robot.contains(id) ? s.per_robot.at(id) : 0.0);
    c << "\n";
  }
  write_text(root / "completeness.csv", c.str(), written);

  std::ostringstream t;
  t << "robot,sim_time_s,x_m,y_m,z_m\n";
  for (const auto& [id, track] : r.robots)
    for (size_t i = 0; i < track.positions_m.size(); ++i)
      t << id << "," << number(i < track.times_s.size() ? track.times_s[i] : 0.0) << ","
        << number(track.positions_m[i].x()) << "," << number(track.positions_m[i].y()) << ","
        << number(track.positions_m[i].z()) << "\n";
  write_text(root / "trajectories.csv", t.str(), written);
  // The same trajectories in TUM format (what evo and most SLAM tools read): one file per
  // robot, "time x y z qx qy qz qw" per line.
  for (const auto& [id, track] : r.robots) {
    std::ostringstream tum;
    tum.precision(9);
    for (size_t i = 0; i < track.positions_m.size(); ++i) {
      const Eigen::Quaterniond q = i < track.orientations.size() ? track.orientations[i] : Eigen::Quaterniond::Identity();
      const Eigen::Vector3d& p = track.positions_m[i];
      tum << (i < track.times_s.size() ? track.times_s[i] : 0.0) << " " << p.x() << " " << p.y() << " " << p.z() << " "
          << q.x() << " " << q.y() << " " << q.z() << " " << q.w() << "\n";
    }
    write_text(root / ("trajectory_" + id + ".tum"), tum.str(), written);
  }

  write_text(root / "communication.csv", communication_csv(r), written);
  write_text(root / "map_transmission.csv", map_transmission_csv(r), written);

  std::ostringstream p;
  p << "robot,round,planning_time_s\n";
  for (const auto& [id, times] : r.planning_times_s)
    for (size_t i = 0; i < times.size(); ++i) p << id << "," << i << "," << number(times[i]) << "\n";
  write_text(root / "planning.csv", p.str(), written);

  std::ostringstream o;
  o << "sim_time_s,robot,key,x_m,y_m,z_m,facade,voxels,covered_voxels,gap,state,attempts\n";
  for (const auto& t : r.open_targets)
    o << number(t.sim_time_s) << "," << t.robot << "," << t.key << "," << number(t.center.x()) << "," << number(t.center.y()) << ","
      << number(t.center.z()) << "," << (t.facade ? 1 : 0) << "," << t.voxels << "," << t.covered_voxels << ","
      << t.gap << "," << t.state << "," << t.attempts << "\n";
  write_text(root / "open_targets.csv", o.str(), written);

  for (auto& file : export_map(r.final_map_points_m, r.map_resolution_m, root.string())) written.push_back(std::move(file));
  return written;
}

std::string multi_run_summary_json(const std::vector<ExperimentRecord>& runs) {
  std::vector<double> time, completeness, observable, accumulated, length, planning, kbps, wall, blocked;
  // Per robot, as the paper reports them: each category's rate, the three map strategies,
  // and the map re-sync totals of the team.
  std::map<std::string, std::vector<double>> category_rate, strategy_rate;
  std::vector<double> gaps_detected, gaps_repaired, collisions;
  for (const auto& r : runs) {
    const double duration = std::max(r.exploration_time_s, 1e-9);
    const double robots = std::max<size_t>(1, r.robots.size());
    for (const auto& category : communication_categories()) {
      uint64_t bytes = 0;
      for (const auto& [_, categories] : r.team_bytes)
        if (auto c = categories.find(category); c != categories.end()) bytes += c->second;
      category_rate[category].push_back(static_cast<double>(bytes) / 1024.0 / robots / duration);
    }
    for (const auto& v : map_strategies(r)) strategy_rate[v.strategy].push_back(v.kb_per_s);
    double detected = 0.0, repaired = 0.0, contacts = 0.0;
    for (const auto& [_, track] : r.robots) {
      detected += track.counter("hlmap.gaps_detected");
      repaired += track.counter("hlmap.gaps_repaired");
      contacts += track.collisions;
    }
    gaps_detected.push_back(detected);
    gaps_repaired.push_back(repaired);
    collisions.push_back(contacts);
    time.push_back(r.exploration_time_s);
    completeness.push_back(r.final_team_completeness());
    observable.push_back(r.completeness.empty() ? 0.0 : r.completeness.back().team_observable);
    accumulated.push_back(r.accumulated_completeness());
    double total_length = 0.0;
    for (const auto& [_, track] : r.robots) total_length += track.length_m;
    length.push_back(total_length);
    double longest_blocked = 0.0;
    for (const auto& [_, track] : r.robots) longest_blocked = std::max(longest_blocked, track.longest_blocked_s);
    blocked.push_back(longest_blocked);
    planning.push_back(mean(all_planning_times(r)));
    kbps.push_back(static_cast<double>(team_bytes_total(r)) / 1024.0 / std::max(r.exploration_time_s, 1e-9));
    wall.push_back(r.wall_time_s);
  }
  auto stat = [](const char* name, const std::vector<double>& v, bool last) {
    const double lo = v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
    const double hi = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    return std::string("  ") + quoted(name) + ": {\"mean\": " + number(mean(v)) + ", \"stddev\": " +
           number(stddev(v)) + ", \"min\": " + number(lo) + ", \"max\": " + number(hi) + "}" + (last ? "\n" : ",\n");
  };
  std::ostringstream j;
  j << "{\n  \"runs\": " << runs.size() << ",\n";
  if (!runs.empty()) {
    j << "  \"scene\": " << quoted(runs.front().scene) << ",\n  \"planner\": " << quoted(runs.front().planner)
      << ",\n  \"mode\": " << quoted(runs.front().mode) << ",\n";
  }
  j << "  \"seeds\": [";
  for (size_t i = 0; i < runs.size(); ++i) j << (i ? ", " : "") << runs[i].seed;
  j << "],\n  \"end_reasons\": [";
  for (size_t i = 0; i < runs.size(); ++i) j << (i ? ", " : "") << quoted(runs[i].end_reason);
  j << "],\n";
  j << stat("exploration_time_s", time, false) << stat("final_completeness", completeness, false)
    << stat("final_observable_completeness", observable, false)
    << stat("accumulated_completeness", accumulated, false) << stat("total_trajectory_length_m", length, false)
    << stat("mean_planning_time_s", planning, false) << stat("team_kb_per_s", kbps, false)
    << stat("collisions", collisions, false) << stat("map_gaps_detected", gaps_detected, false)
    << stat("map_gaps_repaired", gaps_repaired, false)
    << stat("longest_blocked_s", blocked, false);
  j << "  \"robot_kb_per_s_by_category\": {\n";
  for (const auto& category : communication_categories())
    j << "  " << stat(category.c_str(), category_rate[category], category == communication_categories().back());
  j << "  },\n  \"map_transmission_kb_per_s\": {\n";
  for (const char* name : {"incremental_high_level", "full_high_level", "full_perception"})
    j << "  " << stat(name, strategy_rate[name], std::string(name) == "full_perception");
  j << "  },\n" << stat("wall_time_s", wall, true);
  j << "}\n";
  return j.str();
}

}  // namespace hexplore::evaluation
