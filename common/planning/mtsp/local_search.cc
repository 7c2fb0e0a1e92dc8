#include "common/planning/mtsp/local_search.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "common/core/clock.h"

namespace hexplore::planning {
namespace {

// Working state: per-route cost and reference term, so a move is scored from the two routes
// it touches plus the maximum over the others.
class Improver {
 public:
  Improver(const FitnessModel& model, std::vector<Route>& routes, int64_t deadline_ns, BudgetClock clock)
      : m_(model), p_(model.problem()), routes_(routes), deadline_ns_(deadline_ns), clock_(clock) {
    costs_.resize(routes.size());
    refs_.resize(routes.size());
    for (size_t r = 0; r < routes.size(); ++r) refresh(int(r));
  }

  double fitness() const { return fitness_with(-1, 0, 0, -1, 0, 0); }
  bool expired() const { return deadline_ns_ != 0 && budget_clock_ns(clock_) > deadline_ns_; }

  bool two_opt(int r) {
    Route& rt = routes_[size_t(r)];
    const int n = int(rt.size());
    const int s = species(r);
    const int depot = p_.depot(r);
    const bool closed = p_.kind == RouteKind::kClosed;
    bool improved = false;
    for (int i = 0; i + 1 < n; ++i) {
      const int prev = i == 0 ? depot : rt[size_t(i - 1)];
      for (int j = i + 1; j < n; ++j) {
        const bool has_next = j + 1 < n || closed;
        const int next = j + 1 < n ? rt[size_t(j + 1)] : depot;
        double delta = leg(s, prev, rt[size_t(j)]) - leg(s, prev, rt[size_t(i)]);
        if (has_next) delta += leg(s, rt[size_t(i)], next) - leg(s, rt[size_t(j)], next);
        if (delta >= -tolerance()) continue;
        const double before = current_;
        if (fitness_with(r, costs_[size_t(r)] + delta, 0.0, -1, 0, 0) >= before - tolerance()) continue;
        std::reverse(rt.begin() + i, rt.begin() + j + 1);
        if (!accept_or_revert(r, -1, before)) {
          std::reverse(rt.begin() + i, rt.begin() + j + 1);
          continue;
        }
        improved = true;
      }
    }
    return improved;
  }

  // Moves one city of route a to the best-scoring first improving position anywhere.
  bool relocate(int a) {
    bool improved = false;
    for (int i = 0; i < int(routes_[size_t(a)].size()); ++i) {
      if (expired()) return improved;
      if (relocate_city(a, i)) improved = true;
    }
    return improved;
  }

 private:
  int species(int r) const { return p_.robots[size_t(r)].species; }
  double leg(int s, int a, int b) const {
    const double v = p_.travel_cost(s, a, b);
    return std::isfinite(v) ? v : kInfeasiblePenalty;
  }
  double exec(int s, int c) const {
    const double v = p_.execution_cost(s, c);
    return std::isfinite(v) ? v : kInfeasiblePenalty;
  }
  double tolerance() const { return 1e-9 * std::max(1.0, std::abs(current_)); }

  void refresh(int r) {
    costs_[size_t(r)] = m_.route_cost(r, routes_[size_t(r)]);
    refs_[size_t(r)] = m_.reference_distance(r, routes_[size_t(r)]);
    current_ = fitness();
  }

  // Fitness if routes ra and rb (-1 = none) had the given cost and reference terms.
  double fitness_with(int ra, double ca, double fa, int rb, double cb, double fb) const {
    double terms = 0.0, mx = 0.0;
    for (size_t r = 0; r < costs_.size(); ++r) {
      double c = costs_[r], f = refs_[r];
      if (int(r) == ra) c = ca, f = fa;
      if (int(r) == rb) c = cb, f = fb;
      terms += m_.route_terms(int(r), c, f);
      mx = std::max(mx, c);
    }
    return m_.combine(terms, mx);
  }

  // After a tentative edit of routes a (and b), keeps it only if the exact fitness improved.
  bool accept_or_revert(int a, int b, double before) {
    const double ca = m_.route_cost(a, routes_[size_t(a)]);
    const double fa = m_.reference_distance(a, routes_[size_t(a)]);
    double cb = 0, fb = 0;
    if (b >= 0) {
      cb = m_.route_cost(b, routes_[size_t(b)]);
      fb = m_.reference_distance(b, routes_[size_t(b)]);
    }
    const double after = fitness_with(a, ca, fa, b, cb, fb);
    if (after >= before - tolerance()) return false;
    costs_[size_t(a)] = ca, refs_[size_t(a)] = fa;
    if (b >= 0) costs_[size_t(b)] = cb, refs_[size_t(b)] = fb;
    current_ = after;
    ++moves;
    return true;
  }

  bool relocate_city(int a, int i) {
    Route& ra = routes_[size_t(a)];
    const int n = int(ra.size());
    const int c = ra[size_t(i)];
    const int sa = species(a);
    const bool closed = p_.kind == RouteKind::kClosed;
    const int prev = i == 0 ? p_.depot(a) : ra[size_t(i - 1)];
    const bool has_next = i + 1 < n || closed;
    const int next = i + 1 < n ? ra[size_t(i + 1)] : p_.depot(a);
    double removal = -leg(sa, prev, c) - exec(sa, c);
    if (has_next) removal += leg(sa, prev, next) - leg(sa, c, next);
    if (n == 1 && closed) removal = -costs_[size_t(a)];
    const double before = current_;
    const double ref_slack = m_.weights().reference;

    for (int b = 0; b < int(routes_.size()); ++b) {
      if (b != a && n - 1 < p_.min_cities_per_robot) continue;
      if (b != a && !p_.eligible(b, c)) continue;
      const int sb = species(b);
      const Route& rb = routes_[size_t(b)];
      // Positions in route b after removal (for b == a the route without c).
      const int m = b == a ? n - 1 : int(rb.size());
      auto at = [&](int k) { return b == a ? ra[size_t(k < i ? k : k + 1)] : rb[size_t(k)]; };
      for (int j = 0; j <= m; ++j) {
        if (b == a && j == i) continue;  // same place
        const int pb = j == 0 ? p_.depot(b) : at(j - 1);
        const bool nb_exists = j < m || closed;
        const int nb = j < m ? at(j) : p_.depot(b);
        double insertion = leg(sb, pb, c) + exec(sb, c);
        if (nb_exists) insertion += leg(sb, c, nb) - leg(sb, pb, nb);
        if (m == 0 && closed) insertion = leg(sb, pb, c) + exec(sb, c) + leg(sb, c, nb);
        double lower;
        if (b == a) {
          const double ca = (n == 1 && closed ? 0.0 : costs_[size_t(a)] + removal) + insertion;
          lower = fitness_with(a, ca, 0.0, -1, 0, 0);
        } else {
          lower = fitness_with(a, costs_[size_t(a)] + removal, 0.0, b, costs_[size_t(b)] + insertion, 0.0);
        }
        // Reference terms are non-negative, so this bound is exact without a reference.
        const double ref_now = m_.has_reference() ? ref_slack * (refs_[size_t(a)] + (b != a ? refs_[size_t(b)] : 0.0)) : 0.0;
        if (lower - ref_now >= before - tolerance()) continue;
        // Tentative move, verified exactly.
        ra.erase(ra.begin() + i);
        Route& target = routes_[size_t(b)];
        target.insert(target.begin() + j, c);
        if (accept_or_revert(a, b == a ? -1 : b, before)) return true;
        target.erase(target.begin() + j);
        ra.insert(ra.begin() + i, c);
      }
    }
    return false;
  }

 public:
  int moves = 0;

 private:
  const FitnessModel& m_;
  const MtspProblem& p_;
  std::vector<Route>& routes_;
  int64_t deadline_ns_;
  BudgetClock clock_;
  std::vector<double> costs_, refs_;
  double current_ = 0.0;
};

}  // namespace

int64_t budget_clock_ns(BudgetClock clock) {
  if (clock == BudgetClock::kWall) return core::monotonic_ns();
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

LocalSearchStats local_search(const FitnessModel& model, std::vector<Route>& routes, int64_t deadline_ns,
                              int max_passes, BudgetClock clock) {
  LocalSearchStats stats;
  Improver improver(model, routes, deadline_ns, clock);
  stats.fitness_before = improver.fitness();
  bool improved = true;
  while (improved && stats.passes < max_passes && !improver.expired()) {
    improved = false;
    ++stats.passes;
    for (int r = 0; r < int(routes.size()); ++r) improved |= improver.two_opt(r);
    for (int r = 0; r < int(routes.size()) && !improver.expired(); ++r) improved |= improver.relocate(r);
  }
  stats.moves = improver.moves;
  stats.fitness_after = improver.fitness();
  return stats;
}

}  // namespace hexplore::planning
