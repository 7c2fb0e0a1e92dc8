#include "common/service/option_catalogue.h"

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "common/service/options.h"

namespace hexplore::service {
namespace {

// Levenshtein distance, for the "did you mean" of a mistyped option.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Options added by add_service_options; a host reads them from its service threads.
std::mutex added_mutex;
std::vector<OptionInfo>& added_options() {
  static std::vector<OptionInfo> added;
  return added;
}

const std::vector<OptionInfo>& builtin_options() {
  static const std::vector<OptionInfo> table = {
      {"autostart", "station", "send StartMission once every robot is heard (true)"},
      {"blocked-s", "planning", "blocked by terrain this long: skip the view (2 s)"},
      {"cycle-ms", "planning", "planning loop period (200 ms)"},
      {"decision-clock", "safety", "sim|wall: the clock of the 0.2 s conflict decisions (sim)"},
      {"dwell", "planning", "per-view|per-target: what a facade view's observation time is spent on (per-view)"},
      {"end-settle-s", "station", "no task views this long ends the mission (5 s)"},
      {"full-snapshot-period-s", "mapping", "full map delta for late joiners (30 s; 0: only at start)"},
      {"give-up-attempts", "planning", "tries of any kind before a target is given up (3)"},
      {"give-up-views", "planning", "distinct spots a target stays open from before it is given up (1)"},
      {"judge-lag-s", "planning", "coverage is judged this long after an observation: map lag (2 s)"},
      {"keep-stretch-m", "planning", "a new round keeps the old route's views this near the leg (5 m)"},
      {"map-file", "mapping", "load the map at start, save it on shutdown and periodically ({robot}: the robot id)"},
      {"max-pose-jump-m", "mapping", "a larger sensor jump between scans is refused (5 m)"},
      {"min-aim-s", "planning", "shortest look at anything (0.5 s)"},
      {"min-replan-s", "planning", "least time between planning rounds (1 s)"},
      {"observable", "station", "compute the observable-completeness mask (true)"},
      {"observe", "planning", "false: never stop to observe at a view (true)"},
      {"observe-reach-m", "planning", "a view at the frontier is reached this near its spot (0.3 m)"},
      {"open-targets-period-s", "station", "how often planners are asked why targets are open (0: at the end)"},
      {"peer-stuck-s", "planning", "a teammate standing still this long is stuck (30 s)"},
      {"peer-timeout-s", "planning", "a teammate silent this long is gone (team file's liveness)"},
      {"progress-period-s", "station", "progress line on stdout (5 s; 0: none)"},
      {"publish-period-s", "mapping", "voxel delta period (0.5 s)"},
      {"reach-m", "planning", "a view is reached this near its spot (1 m)"},
      {"real-time-factor", "sim", "sim seconds per wall second (1)"},
      {"reanchor-after", "mapping", "consistent jumped scans accepted as a relocation (10)"},
      {"report", "station", "draw the figures at the end of a mission (true)"},
      {"report-script", "station", "what draws them from the results folder"},
      {"results", "station", "results folder (results/latest)"},
      {"save-period-s", "mapping", "map file save period (60 s; 0: only on shutdown)"},
      {"scan-hz", "sim", "LiDAR frames per sim second, every sensor (2)"},
      {"scene-dir", "sim", "write the generated scene mesh there"},
      {"snapshot-period-s", "station", "how often robots' maps are fetched for completeness (10 s)"},
      {"start-wait-s", "station", "start even if some robot is silent this long (60 s)"},
      {"step-hz", "sim", "motion steps and pose messages per sim second (20)"},
      {"stuck-s", "planning", "no 0.5 m of progress this long: skip the view (8 s)"},
      {"switch-gain-m", "planning", "the leg gives way to a first view this much nearer by path (3 m)"},
      {"teammate-timeout-s", "mapping", "a teammate's map silent this long is gone (team file's liveness)"},
      {"trace-dir", "planning, safety", "write each planning round and safety decision as JSON lines there"},
      {"trace-graph-period-s", "planning", "with --trace-dir: the traversal graph as PLY this often (0: never)"},
      {"wait-for-start", "planning, safety", "hold still until the station's StartMission (false)"},
  };
  return table;
}

}  // namespace

std::vector<OptionInfo> service_option_catalogue() {
  std::vector<OptionInfo> table = builtin_options();
  const std::lock_guard<std::mutex> lock(added_mutex);
  table.insert(table.end(), added_options().begin(), added_options().end());
  return table;
}

void add_service_options(const std::vector<OptionInfo>& options) {
  for (const OptionInfo& o : options)
    if (is_service_option(o.name))
      throw std::logic_error("--" + std::string(o.name) + " is already a service option");
  const std::lock_guard<std::mutex> lock(added_mutex);
  added_options().insert(added_options().end(), options.begin(), options.end());
}

bool is_service_option(std::string_view name) {
  const auto table = service_option_catalogue();
  return std::any_of(table.begin(), table.end(), [&](const OptionInfo& o) { return o.name == name; });
}

std::string unknown_option_message(std::string_view name) {
  std::string_view nearest;
  size_t best = name.size() / 2 + 1;  // a suggestion must share more than half the name
  for (const OptionInfo& o : service_option_catalogue())
    if (const size_t d = edit_distance(name, o.name); d < best) best = d, nearest = o.name;
  std::string message = "is no service's option";
  if (!nearest.empty()) message += " (did you mean --" + std::string(nearest) + "?)";
  return message + "; --help lists them";
}

void require_service_options(const std::map<std::string, std::string>& arguments) {
  for (const auto& [key, value] : arguments)
    if (!is_service_option(key)) throw OptionError(key, unknown_option_message(key));
}

std::string service_options_help() {
  std::string out;
  for (const OptionInfo& o : service_option_catalogue()) {
    std::string line = "  --" + std::string(o.name);
    line.resize(std::max<size_t>(line.size() + 1, 28), ' ');
    out += line + "(" + std::string(o.services) + ") " + std::string(o.summary) + "\n";
  }
  return out;
}

}  // namespace hexplore::service
