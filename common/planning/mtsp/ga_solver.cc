#include "common/planning/mtsp/ga_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/core/clock.h"
#include "common/core/rng.h"

namespace hexplore::planning {
namespace {

enum class Op { kNone, kSwap, kShift, kShuffle, kInversion, kTransfer };

struct Individual {
  std::vector<Route> routes;
  double fitness = 0.0;
};

class Ga {
 public:
  Ga(const FitnessModel& model, const GaOptions& options)
      : m_(model), p_(model.problem()), o_(options), rng_(options.seed) {
    species_robots_.resize(size_t(p_.num_species));
    for (int r = 0; r < int(p_.robots.size()); ++r) species_robots_[size_t(p_.robots[size_t(r)].species)].push_back(r);
    // Species a public city may join: those with at least one robot able to serve it.
    public_options_.resize(size_t(p_.num_cities));
    for (int c = 0; c < p_.num_cities; ++c) {
      if (p_.label(c) != kPublic) continue;
      for (int s = 0; s < p_.num_species; ++s)
        for (int r : species_robots_[size_t(s)])
          if (p_.eligible(r, c)) {
            public_options_[size_t(c)].push_back(s);
            break;
          }
    }
    ops_ = {Op::kNone, Op::kSwap, Op::kShift, Op::kShuffle};
    if (o_.use_inversion) ops_.push_back(Op::kInversion);
    for (int c = 0; c < p_.num_cities; ++c)
      if (public_options_[size_t(c)].size() > 1) transferable_.push_back(c);
    if (o_.public_transfer && !transferable_.empty()) ops_.push_back(Op::kTransfer);
  }

  GaResult run() {
    const int64_t start = budget_clock_ns(o_.budget_clock);
    const int64_t wall_start = core::monotonic_ns();
    // With a final local search the generations stop at 90 % of the budget to leave it room.
    const bool final_ls = o_.local_search != LocalSearchMode::kNone;
    const int64_t hard_deadline = o_.time_budget_s > 0 ? start + core::s_to_ns(o_.time_budget_s) : 0;
    const int64_t deadline =
        o_.time_budget_s > 0 ? start + core::s_to_ns(o_.time_budget_s * (final_ls ? 0.9 : 1.0)) : 0;
    const int group = int(2 * ops_.size());
    const int size = std::max(group, (o_.population + group - 1) / group * group);

    std::vector<Individual> pop;
    pop.reserve(size_t(size));
    for (const auto& seed : o_.seeds)
      if (int(pop.size()) < size && valid_seed(seed)) pop.push_back({seed, 0.0});
    while (int(pop.size()) < size) pop.push_back({random_individual(), 0.0});
    for (auto& ind : pop) ind.fitness = evaluate(ind.routes);

    Individual best = *std::min_element(pop.begin(), pop.end(), by_fitness);
    GaResult result;
    result.initial_best_fitness = best.fitness;
    if (o_.local_search == LocalSearchMode::kMemetic || o_.local_search == LocalSearchMode::kOffspring)
      improve(best, deadline);

    std::vector<Individual> next(static_cast<size_t>(size));
    std::vector<int> order(static_cast<size_t>(size));
    int stall = 0;
    int gen = 0;
    while (true) {
      if (o_.max_generations > 0 && gen >= o_.max_generations) break;
      if (o_.max_generations <= 0 && deadline == 0) break;  // nothing bounds the run
      if (deadline != 0 && budget_clock_ns(o_.budget_clock) > deadline) break;
      if (o_.stall_generations > 0 && stall >= o_.stall_generations) break;
      ++gen;
      for (int i = 0; i < size; ++i) order[size_t(i)] = i;
      rng_.shuffle(order);
      for (int g = 0; g < size; g += group) {
        int bi = order[size_t(g)];
        for (int k = 1; k < group; ++k)
          if (pop[size_t(order[size_t(g + k)])].fitness < pop[size_t(bi)].fitness) bi = order[size_t(g + k)];
        const Individual& parent = pop[size_t(bi)];
        next[size_t(g)] = parent;
        for (int k = 1; k < group; ++k) {
          Individual& child = next[size_t(g + k)];
          child.routes = parent.routes;
          mutate(child.routes, ops_[size_t(k % int(ops_.size()))], k >= int(ops_.size()));
          if (o_.local_search == LocalSearchMode::kOffspring) local_search(m_, child.routes, deadline, 1000, o_.budget_clock);
          child.fitness = evaluate(child.routes);
        }
      }
      pop.swap(next);
      const auto it = std::min_element(pop.begin(), pop.end(), by_fitness);
      if (it->fitness < best.fitness - 1e-12 * std::max(1.0, std::abs(best.fitness))) {
        best = *it;
        stall = 0;
        if (o_.local_search == LocalSearchMode::kMemetic) {
          improve(best, deadline);
          *it = best;
        }
      } else {
        ++stall;
      }
    }
    if (final_ls) improve(best, hard_deadline);

    result.routes = best.routes;
    result.breakdown = m_.evaluate(best.routes);
    result.generations = gen;
    result.evaluations = evaluations_;
    result.elapsed_s = core::ns_to_s(core::monotonic_ns() - wall_start);
    result.feasible = result.breakdown.infeasible == 0;
    return result;
  }

 private:
  static bool by_fitness(const Individual& a, const Individual& b) { return a.fitness < b.fitness; }

  double evaluate(const std::vector<Route>& routes) {
    ++evaluations_;
    return m_.fitness(routes);
  }

  void improve(Individual& ind, int64_t deadline) {
    local_search(m_, ind.routes, deadline, 1000, o_.budget_clock);
    ind.fitness = evaluate(ind.routes);
  }

  bool valid_seed(const std::vector<Route>& routes) const {
    if (routes.size() != p_.robots.size()) return false;
    std::vector<char> seen(size_t(p_.num_cities), 0);
    int count = 0;
    for (size_t r = 0; r < routes.size(); ++r) {
      if (int(routes[r].size()) < p_.min_cities_per_robot) return false;
      for (int c : routes[r]) {
        if (c < 0 || c >= p_.num_cities || seen[size_t(c)]) return false;
        if (!p_.eligible(int(r), c)) return false;
        seen[size_t(c)] = 1;
        ++count;
      }
    }
    return count == p_.num_cities;
  }

  // Random sizes summing to n over k robots, each at least min_size (random cut points).
  std::vector<int> random_lengths(int n, int k) {
    const int min_size = std::min(p_.min_cities_per_robot, k > 0 ? n / k : 0);
    const int free = n - k * min_size;
    std::vector<int> cuts(size_t(k - 1));
    for (auto& c : cuts) c = int(rng_.below(uint64_t(free) + 1));
    std::sort(cuts.begin(), cuts.end());
    std::vector<int> lengths(static_cast<size_t>(k));
    int prev = 0;
    for (int i = 0; i < k - 1; ++i) {
      lengths[size_t(i)] = min_size + cuts[size_t(i)] - prev;
      prev = cuts[size_t(i)];
    }
    lengths[size_t(k - 1)] = min_size + free - prev;
    return lengths;
  }

  // Paper "Population Generation": public cities join a random species' private set, then
  // each augmented set is shuffled and split among that species' robots.
  std::vector<Route> random_individual() {
    std::vector<std::vector<int>> sets(size_t(p_.num_species));
    for (int c = 0; c < p_.num_cities; ++c) {
      const int l = p_.label(c);
      if (l != kPublic) {
        sets[size_t(l)].push_back(c);
      } else {
        const auto& opts = public_options_[size_t(c)];
        sets[size_t(opts[size_t(rng_.index(opts.size()))])].push_back(c);
      }
    }
    std::vector<Route> routes(p_.robots.size());
    for (int s = 0; s < p_.num_species; ++s) {
      const auto& robots = species_robots_[size_t(s)];
      if (robots.empty()) continue;
      auto& set = sets[size_t(s)];
      rng_.shuffle(set);
      distribute(set, random_lengths(int(set.size()), int(robots.size())), robots, routes);
      // A random split can hand a city to a robot that cannot reach it (another component of
      // the topology graph); move such cities to a random robot of the species that can.
      for (int r : robots) {
        Route& rt = routes[size_t(r)];
        for (size_t i = 0; i < rt.size();) {
          const int c = rt[i];
          if (p_.eligible(r, c)) {
            ++i;
            continue;
          }
          std::vector<int> able;
          for (int q : robots)
            if (p_.eligible(q, c)) able.push_back(q);
          if (able.empty()) {
            ++i;
            continue;
          }
          rt.erase(rt.begin() + long(i));
          routes[size_t(able[size_t(rng_.index(able.size()))])].push_back(c);
        }
      }
    }
    return routes;
  }

  static void distribute(const std::vector<int>& merged, const std::vector<int>& lengths, const std::vector<int>& robots,
                         std::vector<Route>& routes) {
    size_t pos = 0;
    for (size_t i = 0; i < robots.size(); ++i) {
      Route& rt = routes[size_t(robots[i])];
      rt.assign(merged.begin() + long(pos), merged.begin() + long(pos + size_t(lengths[i])));
      pos += size_t(lengths[i]);
    }
  }

  // Paper "Mutation Operations": per species, merge its robots' routes, mutate the merged
  // set, and redistribute it (same sizes, or new random sizes when `rebreak`).
  void mutate(std::vector<Route>& routes, Op op, bool rebreak) {
    if (op == Op::kTransfer) {
      transfer(routes);
      op = Op::kNone;
    }
    std::vector<int> merged;
    std::vector<int> lengths;
    for (const auto& robots : species_robots_) {
      if (robots.empty()) continue;
      merged.clear();
      lengths.clear();
      for (int r : robots) {
        merged.insert(merged.end(), routes[size_t(r)].begin(), routes[size_t(r)].end());
        lengths.push_back(int(routes[size_t(r)].size()));
      }
      const int n = int(merged.size());
      if (n >= 2 && op != Op::kNone) {
        int i = rng_.index(size_t(n));
        int j = rng_.index(size_t(n));
        if (i == j) j = (i + 1) % n;
        if (i > j) std::swap(i, j);
        switch (op) {
          case Op::kSwap:
            std::swap(merged[size_t(i)], merged[size_t(j)]);
            break;
          case Op::kShift: {
            const int len = j - i + 1;
            const int k = 1 + rng_.index(size_t(len - 1));
            std::rotate(merged.begin() + i, merged.begin() + i + k, merged.begin() + j + 1);
            break;
          }
          case Op::kShuffle:
            rng_.shuffle(merged, size_t(i), size_t(j + 1));
            break;
          case Op::kInversion:
            std::reverse(merged.begin() + i, merged.begin() + j + 1);
            break;
          case Op::kNone:
          case Op::kTransfer:
            break;
        }
      }
      if (rebreak && robots.size() > 1) lengths = random_lengths(n, int(robots.size()));
      distribute(merged, lengths, robots, routes);
    }
  }

  // Moves a random public city to a random position of a robot of another species.
  void transfer(std::vector<Route>& routes) {
    const int c = transferable_[size_t(rng_.index(transferable_.size()))];
    int owner = -1;
    size_t at = 0;
    for (size_t r = 0; r < routes.size() && owner < 0; ++r)
      for (size_t i = 0; i < routes[r].size(); ++i)
        if (routes[r][i] == c) {
          owner = int(r);
          at = i;
          break;
        }
    if (owner < 0 || int(routes[size_t(owner)].size()) <= p_.min_cities_per_robot) return;
    const int from_species = p_.robots[size_t(owner)].species;
    std::vector<int> targets;
    for (int r = 0; r < int(routes.size()); ++r)
      if (p_.robots[size_t(r)].species != from_species && p_.eligible(r, c)) targets.push_back(r);
    if (targets.empty()) return;
    const int to = targets[size_t(rng_.index(targets.size()))];
    routes[size_t(owner)].erase(routes[size_t(owner)].begin() + long(at));
    Route& dst = routes[size_t(to)];
    dst.insert(dst.begin() + long(rng_.below(dst.size() + 1)), c);
  }

  const FitnessModel& m_;
  const MtspProblem& p_;
  GaOptions o_;
  std::vector<int> transferable_;
  core::PlanRng rng_;
  std::vector<std::vector<int>> species_robots_;
  std::vector<std::vector<int>> public_options_;
  std::vector<Op> ops_;
  int64_t evaluations_ = 0;
};

}  // namespace

GaResult solve_ga(const FitnessModel& model, const GaOptions& options) {
  validate(model.problem());
  if (options.population < 1) throw std::invalid_argument("GaOptions.population must be positive");
  return Ga(model, options).run();
}

GaResult solve_brute_force(const FitnessModel& model) {
  const MtspProblem& p = model.problem();
  validate(p);
  if (p.num_cities > 9) throw std::invalid_argument("solve_brute_force: at most 9 cities");
  const int n = p.num_cities;
  const int k = int(p.robots.size());
  std::vector<int> perm(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) perm[size_t(i)] = i;
  GaResult best;
  best.breakdown.fitness = kInfinity;
  std::vector<Route> routes(static_cast<size_t>(k));
  std::vector<int> lengths(size_t(k), 0);
  // Every ordered partition is a permutation cut into k consecutive pieces.
  auto for_each_composition = [&](auto&& self, int robot, int left, auto&& visit) -> void {
    if (robot == k - 1) {
      if (left < p.min_cities_per_robot) return;
      lengths[size_t(robot)] = left;
      visit();
      return;
    }
    for (int len = p.min_cities_per_robot; len <= left; ++len) {
      lengths[size_t(robot)] = len;
      self(self, robot + 1, left - len, visit);
    }
  };
  int64_t evaluations = 0;
  do {
    for_each_composition(for_each_composition, 0, n, [&] {
      size_t pos = 0;
      for (int r = 0; r < k; ++r) {
        routes[size_t(r)].assign(perm.begin() + long(pos), perm.begin() + long(pos + size_t(lengths[size_t(r)])));
        pos += size_t(lengths[size_t(r)]);
      }
      ++evaluations;
      const double f = model.fitness(routes);
      if (f < best.breakdown.fitness) {
        best.breakdown.fitness = f;
        best.routes = routes;
      }
    });
  } while (std::next_permutation(perm.begin(), perm.end()));
  best.breakdown = model.evaluate(best.routes);
  best.initial_best_fitness = best.breakdown.fitness;
  best.evaluations = evaluations;
  best.feasible = best.breakdown.infeasible == 0;
  return best;
}

}  // namespace hexplore::planning
