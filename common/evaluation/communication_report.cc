#include "common/evaluation/communication_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hexplore::evaluation {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

uint64_t category_value(const std::map<std::string, std::map<std::string, uint64_t>>& table, const std::string& robot,
                        const std::string& category) {
  auto r = table.find(robot);
  if (r == table.end()) return 0;
  auto c = r->second.find(category);
  return c == r->second.end() ? 0 : c->second;
}

// The map re-sync and radio counters of summary.json, by the status counter they come from.
const std::vector<std::pair<std::string, std::string>>& sync_counters() {
  static const std::vector<std::pair<std::string, std::string>> k = {{"gaps_detected", "hlmap.gaps_detected"},
                                                                     {"gaps_repaired", "hlmap.gaps_repaired"},
                                                                     {"repair_requests", "hlmap.repair_requests"},
                                                                     {"snapshots_applied", "hlmap.snapshots_applied"},
                                                                     {"peer_restarts", "hlmap.peer_restarts"},
                                                                     {"digests_checked", "hlmap.digests_checked"},
                                                                     {"digest_mismatches", "hlmap.digest_mismatches"}};
  return k;
}
const std::vector<std::pair<std::string, std::string>>& radio_counters() {
  static const std::vector<std::pair<std::string, std::string>> k = {
      {"expired", "radio_expired"}, {"lost", "radio_lost"}, {"out_of_range", "radio_out_of_range"}};
  return k;
}

}  // namespace

std::vector<StrategyVolume> map_strategies(const ExperimentRecord& r) {
  const double robots = std::max<size_t>(1, r.robots.size());
  const double duration = std::max(r.exploration_time_s, 1e-9);
  double incremental = 0.0, full = 0.0, raw = 0.0;
  for (const auto& [id, track] : r.robots) {
    incremental += static_cast<double>(category_value(r.team_bytes, id, "incremental_map"));
    full += track.counter("hlmap.full_map_bytes");
    raw += track.counter("mapping.raw_map_bytes");
  }
  auto volume = [&](const char* name, double bytes) {
    const double kb = bytes / 1024.0 / robots;
    return StrategyVolume{name, kb, kb / duration};
  };
  return {volume("incremental_high_level", incremental), volume("full_high_level", full),
          volume("full_perception", raw)};
}

std::string map_transmission_json(const ExperimentRecord& r) {
  const auto strategies = map_strategies(r);
  std::ostringstream j;
  j << "{";
  for (const auto& s : strategies)
    j << "\"" << s.strategy << "\": {\"cumulative_kb\": " << number(s.cumulative_kb)
      << ", \"average_kb_per_s\": " << number(s.kb_per_s) << "}, ";
  auto saving = [&](size_t other) {
    return strategies[other].cumulative_kb > 0.0 ? 1.0 - strategies[0].cumulative_kb / strategies[other].cumulative_kb
                                                 : 0.0;
  };
  j << "\"saving_vs_full_high_level\": " << number(saving(1)) << ", \"saving_vs_full_perception\": "
    << number(saving(2)) << "}";
  return j.str();
}

std::string robot_communication_json(const ExperimentRecord& r, const std::string& robot) {
  std::ostringstream j;
  j << "\"communication_messages\": {";
  bool first = true;
  for (const auto& category : communication_categories()) {
    j << (first ? "" : ", ") << "\"" << category << "\": " << category_value(r.team_messages, robot, category);
    first = false;
  }
  j << "}";
  const auto it = r.robots.find(robot);
  if (it == r.robots.end()) return j.str();
  j << ", \"map_sync\": {";
  first = true;
  for (const auto& [name, key] : sync_counters()) {
    j << (first ? "" : ", ") << "\"" << name << "\": " << number(it->second.counter(key));
    first = false;
  }
  // Each teammate's increments this robot had not applied at the end (null: never heard).
  j << ", \"increments_behind\": {";
  first = true;
  for (const auto& [source, _] : r.robots) {
    if (source == robot) continue;
    const double behind = r.increments_behind(robot, source);
    j << (first ? "" : ", ") << "\"" << source << "\": " << (behind < 0 ? "null" : number(behind));
    first = false;
  }
  // When each teammate's contribution, as held here, differed from what it sent: how often,
  // the longest stretch, and when the last one ended (null: never / still open at the end).
  j << "}, \"out_of_sync\": {";
  first = true;
  for (const auto& [source, stretches] : it->second.unsynced) {
    double longest = 0.0;
    for (const auto& [from, to] : stretches) longest = std::max(longest, (to < 0 ? r.exploration_time_s : to) - from);
    const bool open = !stretches.empty() && stretches.back().second < 0;
    j << (first ? "" : ", ") << "\"" << source << "\": {\"stretches\": " << stretches.size()
      << ", \"longest_s\": " << number(longest) << ", \"last_resynced_s\": "
      << (stretches.empty() || open ? "null" : number(stretches.back().second))
      << ", \"open_at_end\": " << (open ? "true" : "false") << "}";
    first = false;
  }
  j << "}}, \"radio_drops\": {";
  first = true;
  for (const auto& [name, value] : radio_counters()) {
    j << (first ? "" : ", ") << "\"" << name << "\": " << number(it->second.counter_sum(value));
    first = false;
  }
  j << "}";
  return j.str();
}

std::string communication_csv(const ExperimentRecord& r) {
  const double duration = std::max(r.exploration_time_s, 1e-9);
  std::ostringstream m;
  m << "robot,category,messages,cumulative_kb,average_kb_per_s\n";
  for (const auto& [id, _] : r.robots)
    for (const auto& category : communication_categories()) {
      const double kb = static_cast<double>(category_value(r.team_bytes, id, category)) / 1024.0;
      m << id << "," << category << "," << category_value(r.team_messages, id, category) << "," << number(kb) << ","
        << number(kb / duration) << "\n";
    }
  return m.str();
}

std::string map_transmission_csv(const ExperimentRecord& r) {
  std::ostringstream m;
  m << "strategy,cumulative_kb,average_kb_per_s\n";
  for (const auto& s : map_strategies(r))
    m << s.strategy << "," << number(s.cumulative_kb) << "," << number(s.kb_per_s) << "\n";
  return m.str();
}

}  // namespace hexplore::evaluation
