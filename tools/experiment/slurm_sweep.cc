#include "tools/experiment/slurm_sweep.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hexplore::experiment {
namespace {

namespace fs = std::filesystem;

// The results folder of one run, as --planners lays them out (a single planner: no subfolder).
fs::path seed_folder(const fs::path& results, const SweepRun& run) {
  const fs::path base = run.planner.empty() ? results : results / run.planner;
  return base / ("seed-" + std::to_string(run.seed));
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

std::vector<SweepRun> sweep_runs(const ExperimentArgs& args) {
  std::vector<std::string> planners = args.planners;
  if (planners.empty()) planners.push_back(args.planner.value_or(""));
  std::vector<SweepRun> runs;
  for (const auto& planner : planners)
    for (uint64_t seed : args.seeds) runs.push_back({planner, seed});
  return runs;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string write_slurm_sweep(const ExperimentArgs& args, const std::string& executable, const std::string& dir) {
  const fs::path root = fs::absolute(dir);
  const fs::path results = fs::absolute(args.results_dir);
  std::error_code ec;
  fs::create_directories(root / "logs", ec);
  if (ec) throw std::runtime_error(root.string() + ": cannot create the sweep folder: " + ec.message());
  const auto runs = sweep_runs(args);

  std::ostringstream table;
  table << "results\t" << results.string() << "\n";
  table << "index\tplanner\tseed\n";
  for (size_t i = 0; i < runs.size(); ++i) table << i << "\t" << runs[i].planner << "\t" << runs[i].seed << "\n";
  write_file(root / "runs.tsv", table.str());

  // The options every task passes on; --trace-dir gets the planner, as --planners does.
  std::string options = " --config " + shell_quoted(fs::absolute(args.config).string()) + " --report false --log-level " +
                        shell_quoted(args.log_level);
  if (args.time_limit_s) options += " --time-limit-s " + std::to_string(*args.time_limit_s);
  for (const auto& robot : args.robots) options += " --robot " + shell_quoted(robot);
  std::string trace_dir;
  for (const auto& [key, value] : args.service_arguments) {
    if (key == "trace-dir") trace_dir = fs::absolute(value).string();
    else options += " --" + key + " " + shell_quoted(value);
  }

  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# A hexplore sweep, one Slurm array task per line of runs.tsv (written by hexplore_experiment\n"
    << "# --emit-slurm). Submit with `sbatch " << (root / "sweep.sbatch").string() << "`; when every task\n"
    << "# has ended, `hexplore_experiment --gather " << root.string() << "` writes the comparison.\n"
    << "#SBATCH --job-name=hexplore-sweep\n"
    << "#SBATCH --array=0-" << runs.size() - 1 << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=1\n"
    << "#SBATCH --output=" << (root / "logs" / "%a.log").string() << "\n"
    << "set -euo pipefail\n"
    << "sweep=" << shell_quoted(root.string()) << "\n"
    << "results=" << shell_quoted(results.string()) << "\n"
    << "row=$(awk -F'\\t' -v i=\"$SLURM_ARRAY_TASK_ID\" '$1 == i { print $2 \"\\t\" $3 }' \"$sweep/runs.tsv\")\n"
    << "[ -n \"$row\" ] || { echo \"no run $SLURM_ARRAY_TASK_ID in $sweep/runs.tsv\" >&2; exit 2; }\n"
    << "planner=$(cut -f1 <<< \"$row\")\n"
    << "seed=$(cut -f2 <<< \"$row\")\n"
    << "echo \"[sweep] task $SLURM_ARRAY_TASK_ID on $(hostname): planner ${planner:-from the team file}, seed $seed\"\n"
    << "# Each task writes into a folder of its own, then moves the seed folder in place: tasks of one\n"
    << "# planner would otherwise overwrite each other's summary.\n"
    << "work=\"$results/.tasks/${planner:-team}-$seed\"\n"
    << "rm -rf \"$work\"\n"
    << "extra=()\n"
    << "[ -n \"$planner\" ] && extra+=(--planner \"$planner\")\n";
  if (!trace_dir.empty())
    s << "extra+=(--trace-dir " << shell_quoted(trace_dir) << "\"${planner:+/$planner}\")\n";
  s << shell_quoted(fs::absolute(executable).string()) << options << " --seeds \"$seed\" --results \"$work\" \"${extra[@]}\"\n"
    << "target=\"$results${planner:+/$planner}/seed-$seed\"\n"
    << "mkdir -p \"$(dirname \"$target\")\"\n"
    << "rm -rf \"$target\"\n"
    << "mv \"$work/seed-$seed\" \"$target\"\n"
    << "rm -rf \"$work\"\n"
    << "echo \"[sweep] task $SLURM_ARRAY_TASK_ID done: $target\"\n";
  const fs::path script = root / "sweep.sbatch";
  write_file(script, s.str());
  fs::permissions(script, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add, ec);
  return script.string();
}

SweepStatus read_sweep(const std::string& dir) {
  const fs::path table = fs::path(dir) / "runs.tsv";
  std::ifstream in(table);
  if (!in) throw std::runtime_error(table.string() + ": cannot read (is " + dir + " a folder hexplore_experiment --emit-slurm wrote?)");
  SweepStatus status;
  std::string line;
  int number = 0;
  auto malformed = [&](const std::string& why) {
    return std::runtime_error(table.string() + ":" + std::to_string(number) + ": " + why);
  };
  while (std::getline(in, line)) {
    ++number;
    std::vector<std::string> fields;
    std::stringstream split(line);
    for (std::string field; std::getline(split, field, '\t');) fields.push_back(field);
    if (number == 1) {
      if (fields.size() != 2 || fields[0] != "results") throw malformed("expected 'results<TAB>FOLDER'");
      status.results_dir = fields[1];
      continue;
    }
    if (number == 2) continue;  // the column names
    if (line.empty()) continue;
    if (fields.size() != 3) throw malformed("expected 'index<TAB>planner<TAB>seed'");
    SweepRun run;
    run.planner = fields[1];
    try {
      size_t used = 0;
      run.seed = std::stoull(fields[2], &used);
      if (used != fields[2].size()) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      throw malformed("'" + fields[2] + "' is not a seed");
    }
    if (std::find(status.planners.begin(), status.planners.end(), run.planner) == status.planners.end())
      status.planners.push_back(run.planner);
    const bool done = fs::is_regular_file(seed_folder(status.results_dir, run) / "summary.json");
    (done ? status.done : status.missing).push_back(run);
  }
  if (status.results_dir.empty()) throw std::runtime_error(table.string() + ": empty");
  return status;
}

}  // namespace hexplore::experiment
