#include "tools/experiment/experiment_args.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "common/service/option_catalogue.h"

namespace hexplore::experiment {

namespace {

// `value` read by `read` (a std::stoi or std::stod call) when all of it is the number, else nullopt.
template <typename Read>
auto read_whole(const std::string& value, Read read) -> std::optional<decltype(read(value, nullptr))> {
  size_t used = 0;
  try {
    const auto v = read(value, &used);
    if (used == value.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

uint64_t to_seed(const std::string& text) {
  size_t used = 0;
  unsigned long long value = 0;
  try {
    value = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || text[0] == '-')
    throw std::invalid_argument("--seeds: '" + text + "' is not a seed (a non-negative integer)");
  return value;
}

}  // namespace

std::vector<uint64_t> parse_seed_list(const std::string& text) {
  std::vector<uint64_t> seeds;
  for (size_t start = 0; start <= text.size();) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    start = comma + 1;
    if (item.empty()) continue;
    if (const size_t dash = item.find('-', 1); dash != std::string::npos) {
      const uint64_t first = to_seed(item.substr(0, dash)), last = to_seed(item.substr(dash + 1));
      if (last < first || last - first >= 1000)
        throw std::invalid_argument("--seeds: range '" + item + "' must go upwards and hold at most 1000 seeds");
      for (uint64_t s = first; s <= last; ++s) seeds.push_back(s);
    } else {
      seeds.push_back(to_seed(item));
    }
  }
  if (seeds.empty()) throw std::invalid_argument("--seeds: no seed given");
  return seeds;
}

std::vector<std::string> parse_planner_list(const std::string& text) {
  std::vector<std::string> names;
  for (size_t start = 0; start <= text.size();) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    start = comma + 1;
    if (item.empty()) continue;
    if (std::find(names.begin(), names.end(), item) != names.end())
      throw std::invalid_argument("--planners: '" + item + "' is listed twice");
    names.push_back(item);
  }
  if (names.empty()) throw std::invalid_argument("--planners: no planner given");
  return names;
}

ExperimentArgs parse_experiment_args(int argc, char** argv) {
  ExperimentArgs a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      a.help = true;
      return a;
    }
    if (flag.rfind("--", 0) != 0 || flag.size() < 3) throw std::invalid_argument("unexpected argument '" + flag + "'");
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + flag);
    const std::string value = argv[++i];
    if (flag == "--config") a.config = value;
    else if (flag == "--seeds") a.seeds = parse_seed_list(value);
    else if (flag == "--results") a.results_dir = value;
    else if (flag == "--planner") a.planner = value;
    else if (flag == "--planners") a.planners = parse_planner_list(value);
    else if (flag == "--jobs") {
      const auto jobs = read_whole(value, [](const std::string& s, size_t* used) { return std::stoi(s, used); });
      if (!jobs || *jobs < 1 || *jobs > 64)
        throw std::invalid_argument("--jobs expects a whole number from 1 to 64, got '" + value + "'");
      a.jobs = *jobs;
    } else if (flag == "--time-limit-s") {
      const auto limit = read_whole(value, [](const std::string& s, size_t* used) { return std::stod(s, used); });
      if (!limit || !std::isfinite(*limit) || *limit <= 0.0 || *limit > 1.0e6)
        throw std::invalid_argument("--time-limit-s expects seconds of sim time, above 0 and at most 1e6, got '" +
                                    value + "'");
      a.time_limit_s = *limit;
    } else if (flag == "--report") {
      if (value != "true" && value != "false") throw std::invalid_argument("--report expects true or false, got '" + value + "'");
      a.report = value == "true";
    } else if (flag == "--report-script") a.report_script = value;
    else if (flag == "--robot") a.robots.push_back(value);
    else if (flag == "--log-level") a.log_level = value;
    else if (flag == "--emit-slurm") a.emit_slurm = value;
    else if (flag == "--gather") a.gather = value;
    else if (service::is_service_option(flag.substr(2))) a.service_arguments[flag.substr(2)] = value;
    else throw std::invalid_argument(flag + " " + service::unknown_option_message(flag.substr(2)));
  }
  if (a.gather) {
    if (!a.config.empty() || !a.seeds.empty() || a.emit_slurm)
      throw std::invalid_argument("--gather DIR takes no --config, --seeds or --emit-slurm: the sweep folder has them");
    return a;
  }
  if (a.config.empty()) throw std::invalid_argument("missing --config TEAM.yaml");
  if (a.seeds.empty()) throw std::invalid_argument("missing --seeds LIST (e.g. 1,2,3 or 1-5)");
  if (a.planner && !a.planners.empty()) throw std::invalid_argument("--planner and --planners exclude each other");
  return a;
}

}  // namespace hexplore::experiment
