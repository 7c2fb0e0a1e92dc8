#include "tools/mtsp_solver/cli.h"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/planning/mtsp/ga_solver.h"
#include "common/planning/mtsp/tsplib.h"
#include "tools/mtsp_solver/species_file.h"

namespace hexplore::mtsp {
namespace {

std::vector<int> parse_int_list(const std::string& flag, const std::string& text) {
  std::vector<int> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      out.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw std::invalid_argument(flag + ": '" + item + "' is not an integer");
    }
  }
  if (out.empty()) throw std::invalid_argument(flag + ": empty list");
  return out;
}

template <typename T>
T parse_number(const std::string& flag, const std::string& text) {
  std::istringstream ss(text);
  T v;
  std::string rest;
  if (!(ss >> v) || (ss >> rest)) throw std::invalid_argument(flag + ": '" + text + "' is not a number");
  return v;
}

}  // namespace

std::string usage() {
  return R"(usage: hexplore_mtsp FILE.tsp [options]

Solves a (heterogeneous, multi-depot) multiple travelling salesman problem over a TSPLIB
coordinate file with the hexplore genetic algorithm and prints the routes and objective.

  FILE.tsp              TSPLIB file: NODE_COORD_SECTION with EDGE_WEIGHT_TYPE EUC_2D,
                        CEIL_2D, ATT or GEO; an optional DEPOT_SECTION gives the default depot
  -m, --salesmen M      number of salesmen (default 1)
  --depot ID            depot node id for every salesman (default: first DEPOT_SECTION
                        entry, else node 1)
  --depots ID,ID,...    one depot node id per salesman (multi-depot)
  --open                routes end at their last city (default: closed, back to the depot)
  --closed              routes return to their depot
  --unrounded           exact Euclidean distances for EUC_2D / CEIL_2D (default: TSPLIB nint)
  --species FILE        species side file, one directive per line ('#' comments):
                          salesman <1..M> <species>
                          city <node id> <species|public>
                        unlisted salesmen get the first species, unlisted cities are public;
                        a private city may only be served by salesmen of its species
  --objective NAME      min-sum (total length), min-max (longest route; total breaks ties),
                        weighted (beta_c * total + beta_m * longest, the paper's fitness
                        without a reference route)
  --beta-c X --beta-m X weights of the weighted objective (default 1.0 and 1.5)
  --time-limit S        wall-clock budget in seconds (default 1.0; 0 = none)
  --generations G       generation budget (default 0 = none); with --time-limit 0 the run
                        is fully deterministic for a seed
  --population N        population size (default 64, rounded up to the group size)
  --seed N              random seed (default 1)
  --local-search MODE   none (the paper's mutation-only GA), final (on the result),
                        memetic (on each new best), offspring (on every mutant; default)
  --no-inversion        only the paper's swap / shift / shuffle mutations
  --min-cities K        smallest number of cities per salesman (default 1)
  -h, --help            this text
)";
}

CliOptions parse_cli(const std::vector<std::string>& args) {
  CliOptions o;
  bool have_file = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "-m" || a == "--salesmen") {
      o.salesmen = parse_number<int>(a, value());
      if (o.salesmen < 1) throw std::invalid_argument(a + " must be at least 1");
    } else if (a == "--depot") {
      o.depots = {parse_number<int>(a, value())};
    } else if (a == "--depots") {
      o.depots = parse_int_list(a, value());
    } else if (a == "--open") {
      o.closed = false;
    } else if (a == "--closed") {
      o.closed = true;
    } else if (a == "--unrounded") {
      o.rounded = false;
    } else if (a == "--species") {
      o.species_file = value();
    } else if (a == "--objective") {
      o.objective = value();
      if (o.objective != "min-sum" && o.objective != "min-max" && o.objective != "weighted")
        throw std::invalid_argument("--objective '" + o.objective + "' is not one of min-sum, min-max, weighted");
    } else if (a == "--beta-c") {
      o.beta_c = parse_number<double>(a, value());
    } else if (a == "--beta-m") {
      o.beta_m = parse_number<double>(a, value());
    } else if (a == "--time-limit") {
      o.time_limit_s = parse_number<double>(a, value());
    } else if (a == "--generations") {
      o.generations = parse_number<int>(a, value());
    } else if (a == "--population") {
      o.population = parse_number<int>(a, value());
      if (o.population < 1) throw std::invalid_argument("--population must be positive");
    } else if (a == "--seed") {
      o.seed = parse_number<uint64_t>(a, value());
    } else if (a == "--local-search") {
      o.local_search = value();
      if (o.local_search != "none" && o.local_search != "final" && o.local_search != "memetic" && o.local_search != "offspring")
        throw std::invalid_argument("--local-search '" + o.local_search + "' is not one of none, final, memetic, offspring");
    } else if (a == "--no-inversion") {
      o.inversion = false;
    } else if (a == "--min-cities") {
      o.min_cities = parse_number<int>(a, value());
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option '" + a + "' (see --help)");
    } else if (!have_file) {
      o.tsp_file = a;
      have_file = true;
    } else {
      throw std::invalid_argument("more than one input file ('" + o.tsp_file + "', '" + a + "')");
    }
  }
  if (!o.help && !have_file) throw std::invalid_argument("no TSPLIB file given (see --help)");
  if (!o.help && o.time_limit_s <= 0 && o.generations <= 0)
    throw std::invalid_argument("give --time-limit > 0 or --generations > 0");
  return o;
}

int run_cli(const CliOptions& o, std::ostream& out, std::ostream& err) {
  if (o.help) {
    out << usage();
    return 0;
  }
  try {
    const planning::TsplibInstance inst = planning::load_tsplib(o.tsp_file);
    std::vector<int> depots = o.depots;
    if (depots.empty()) depots = {inst.depots.empty() ? 1 : inst.depots.front() + 1};
    if (depots.size() == 1) depots.assign(size_t(o.salesmen), depots.front());
    if (int(depots.size()) != o.salesmen)
      throw std::invalid_argument("--depots lists " + std::to_string(depots.size()) + " depots for " +
                                  std::to_string(o.salesmen) + " salesmen");
    for (int& d : depots) {
      if (d < 1 || d > inst.dimension())
        throw std::invalid_argument("depot " + std::to_string(d) + " outside 1.." + std::to_string(inst.dimension()));
      --d;
    }
    SpeciesAssignment species;
    if (!o.species_file.empty()) {
      species = load_species_file(o.species_file, o.salesmen, inst.dimension());
    } else {
      species.species = {"default"};
      species.salesman_species.assign(size_t(o.salesmen), 0);
    }
    auto built = planning::make_tsplib_mtsp(inst, depots, species.salesman_species, species.node_species,
                                            int(species.species.size()),
                                            o.closed ? planning::RouteKind::kClosed : planning::RouteKind::kOpen, o.rounded);
    built.problem.min_cities_per_robot = std::min(o.min_cities, built.problem.num_cities / o.salesmen);
    planning::FitnessWeights w = planning::FitnessWeights::min_sum();
    if (o.objective == "min-max") w = planning::FitnessWeights::min_max();
    if (o.objective == "weighted") w = {o.beta_c, o.beta_m, 0.0, 0.5};
    const planning::FitnessModel model(built.problem, w);
    planning::GaOptions ga;
    ga.population = o.population;
    ga.max_generations = o.generations;
    ga.time_budget_s = o.time_limit_s;
    ga.seed = o.seed;
    ga.use_inversion = o.inversion;
    ga.local_search = o.local_search == "none"    ? planning::LocalSearchMode::kNone
                      : o.local_search == "final"   ? planning::LocalSearchMode::kFinal
                      : o.local_search == "memetic" ? planning::LocalSearchMode::kMemetic
                                                    : planning::LocalSearchMode::kOffspring;
    const planning::GaResult r = planning::solve_ga(model, ga);

    out << "instance " << (inst.name.empty() ? o.tsp_file : inst.name) << ": " << inst.dimension() << " nodes, "
        << built.problem.num_cities << " cities, " << o.salesmen << " salesmen, "
        << (o.closed ? "closed" : "open") << " routes, " << (o.rounded ? "rounded" : "unrounded")
        << " distances, objective " << o.objective << "\n";
    out << std::fixed << std::setprecision(o.rounded ? 0 : 3);
    for (size_t s = 0; s < r.routes.size(); ++s) {
      out << "salesman " << s + 1;
      if (species.species.size() > 1) out << " [" << species.species[size_t(species.salesman_species[s])] << "]";
      out << " cost " << r.breakdown.costs[s] << ": " << depots[s] + 1;
      for (int c : r.routes[s]) out << " " << built.city_node[size_t(c)] + 1;
      if (o.closed && !r.routes[s].empty()) out << " " << depots[s] + 1;
      out << "\n";
    }
    out << "total " << r.breakdown.sum_cost << "\n";
    out << "longest " << r.breakdown.max_cost << "\n";
    out << std::setprecision(3) << "objective " << r.breakdown.fitness << "\n";
    out << "generations " << r.generations << ", evaluations " << r.evaluations << ", elapsed_s " << r.elapsed_s
        << ", feasible " << (r.feasible ? "yes" : "no") << "\n";
    return r.feasible ? 0 : 3;
  } catch (const std::exception& e) {
    err << "hexplore_mtsp: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace hexplore::mtsp
