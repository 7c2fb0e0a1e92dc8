// Solver quality on classic TSPLIB instances as min-sum and min-max mTSP (closed routes,
// common depot = node 1, every salesman visits at least one city, TSPLIB-rounded distances).
// Prints, per instance and number of salesmen, the result of each solver mode within the
// time budget and its gap to the reference value: the best value this solver found in long
// runs (data/mtsp_long_run_best.txt, regenerated with --long-run), or any better value found
// in this run. These are NOT published best-known values (none were at hand); the TSP optimum
// of each instance (a lower bound for min-sum) is printed alongside as a sanity check.
// Budgets count the thread's CPU time, so a loaded machine does not shorten the runs.
// Usage: bench_mtsp_quality [--time S] [--long-run S] [--seeds N] [--instances a,b]

#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/planning/mtsp/ga_solver.h"
#include "common/planning/mtsp/tsplib.h"

using namespace hexplore::planning;

namespace {

struct Mode {
  const char* name;
  LocalSearchMode ls;
  bool inversion;
};

const Mode kModes[] = {
    {"paper-ga", LocalSearchMode::kNone, false},     // swap / shift / shuffle only
    {"ga+final-ls", LocalSearchMode::kFinal, true},  // + inversion, local search on the result
    {"memetic", LocalSearchMode::kOffspring, true},  // local search on every mutant
};

const std::map<std::string, double> kTspOptimum = {{"eil51", 426}, {"berlin52", 7542}, {"eil76", 538}, {"kroA100", 21282}};

double solve(const TsplibInstance& inst, int m, bool min_max, const Mode& mode, double seconds, uint64_t seed) {
  TsplibMtsp built = make_tsplib_mtsp(inst, std::vector<int>(size_t(m), 0), {}, {}, 1, RouteKind::kClosed, true);
  built.problem.min_cities_per_robot = 1;
  const FitnessModel model(built.problem, min_max ? FitnessWeights::min_max() : FitnessWeights::min_sum());
  GaOptions o;
  o.max_generations = 0;
  o.time_budget_s = seconds;
  o.budget_clock = BudgetClock::kThreadCpu;  // the machine is shared: count our CPU time
  o.seed = seed;
  o.use_inversion = mode.inversion;
  o.local_search = mode.ls;
  const GaResult r = solve_ga(model, o);
  return min_max ? r.breakdown.max_cost : r.breakdown.sum_cost;
}

std::string key(const std::string& inst, int m, bool min_max) {
  return inst + " " + std::to_string(m) + " " + (min_max ? "min-max" : "min-sum");
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 1.0, long_run = 0.0;
  int seeds = 1;
  std::vector<std::string> names = {"eil51", "berlin52", "eil76", "kroA100"};
  for (int i = 1; i < argc; ++i) {
    auto next = [&] { return i + 1 < argc ? argv[++i] : ""; };
    if (!std::strcmp(argv[i], "--time")) seconds = std::atof(next());
    else if (!std::strcmp(argv[i], "--long-run")) long_run = std::atof(next());
    else if (!std::strcmp(argv[i], "--seeds")) seeds = std::atoi(next());
    else if (!std::strcmp(argv[i], "--instances")) {
      names.clear();
      std::stringstream ss(next());
      for (std::string n; std::getline(ss, n, ',');) names.push_back(n);
    } else {
      std::fprintf(stderr, "usage: %s [--time S] [--long-run S] [--seeds N] [--instances a,b]\n", argv[0]);
      return 2;
    }
  }
  const std::string dir = HEXPLORE_MTSP_DATA_DIR;
  const int salesmen[] = {2, 3, 5, 7};

  if (long_run > 0) {
    // Prints lines for data/mtsp_long_run_best.txt.
    std::printf("# instance salesmen objective best  (memetic mode, %d seed(s) x %.0f s)\n", seeds, long_run);
    for (const auto& name : names) {
      const TsplibInstance inst = load_tsplib(dir + "/" + name + ".tsp");
      for (int m : salesmen)
        for (bool mm : {false, true}) {
          double best = 1e300;
          for (int s = 1; s <= seeds; ++s) best = std::min(best, solve(inst, m, mm, kModes[2], long_run, 1000 + s));
          std::printf("%s %.0f\n", key(name, m, mm).c_str(), best);
          std::fflush(stdout);
        }
    }
    return 0;
  }

  std::map<std::string, double> reference;
  std::ifstream in(dir + "/mtsp_long_run_best.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string inst, obj;
    int m;
    double v;
    if (ls >> inst >> m >> obj >> v) reference[inst + " " + std::to_string(m) + " " + obj] = v;
  }

  std::printf("TSP optimum (lower bound for min-sum):");
  for (const auto& name : names) std::printf(" %s %.0f", name.c_str(), kTspOptimum.count(name) ? kTspOptimum.at(name) : 0.0);
  std::printf("\n%-10s %2s %-8s %10s", "instance", "m", "obj", "reference");
  for (const auto& mode : kModes) std::printf(" %12s %7s", mode.name, "gap%");
  std::printf("\n");
  std::map<std::string, std::pair<double, int>> gap_sum;  // mode/objective -> (sum, count)
  for (const auto& name : names) {
    const TsplibInstance inst = load_tsplib(dir + "/" + name + ".tsp");
    for (bool mm : {false, true})
      for (int m : salesmen) {
        std::vector<double> values;
        for (const auto& mode : kModes) {
          double best = 1e300;
          for (int s = 1; s <= seeds; ++s) best = std::min(best, solve(inst, m, mm, mode, seconds, uint64_t(s)));
          values.push_back(best);
        }
        const auto it = reference.find(key(name, m, mm));
        double ref = it != reference.end() ? it->second : 1e300;
        for (double v : values) ref = std::min(ref, v);
        std::printf("%-10s %2d %-8s %10.0f", name.c_str(), m, mm ? "min-max" : "min-sum", ref);
        for (size_t k = 0; k < values.size(); ++k) {
          const double gap = 100.0 * (values[k] - ref) / ref;
          std::printf(" %12.0f %7.2f", values[k], gap);
          auto& g = gap_sum[std::string(kModes[k].name) + (mm ? " min-max" : " min-sum")];
          g.first += gap;
          g.second += 1;
        }
        std::printf("\n");
        std::fflush(stdout);
      }
  }
  std::printf("\naverage gap (%%), %.2f s per run, best of %d seed(s):\n", seconds, seeds);
  for (const auto& [k, v] : gap_sum) std::printf("  %-22s %6.2f\n", k.c_str(), v.first / v.second);
  return 0;
}
