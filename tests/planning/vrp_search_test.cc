// The MDVRP+ solver: cheapest insertion, guided local search never worse than its start,
// optimal on tiny instances, capability (+inf) respected, deterministic per seed.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "common/core/rng.h"
#include "common/planning/vrp_search.h"

namespace hexplore::planning {
namespace {

// Customers and depots at random points of a 50 m square; two classes of vehicle (speeds
// 0.4 and 0.5 m/s), class 0 cannot serve customers with index % 4 == 3 (its +inf), class 1
// cannot serve those with index % 5 == 4 that class 0 can (so someone can serve each);
// facade-like service of 2 s on every third customer.
VrpInstance random_instance(int customers, int vehicles, uint64_t seed) {
  core::PlanRng rng(seed);
  VrpInstance in;
  in.customers = customers;
  for (int v = 0; v < vehicles; ++v) in.vehicle_class.push_back(v % 2);
  const int n = customers + vehicles;
  std::vector<Eigen::Vector2d> p(static_cast<size_t>(n));
  for (auto& x : p) x = {50.0 * rng.uniform(), 50.0 * rng.uniform()};
  for (int c = 0; c < 2; ++c) {
    const double speed = c == 0 ? 0.4 : 0.5;
    auto can = [&](int node) { return node >= customers || (c == 0 ? node % 4 != 3 : node % 5 != 4 || node % 4 == 3); };
    CostMatrix m(n, kInfinity);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        if (b >= customers) continue;  // open routes: nobody travels into a depot
        if (a >= customers && in.vehicle_class[size_t(a - customers)] != c) continue;
        if (!can(a) || !can(b)) continue;
        m.set(a, b, (p[size_t(a)] - p[size_t(b)]).norm() / speed);
      }
    in.travel.push_back(std::move(m));
    std::vector<double> s(static_cast<size_t>(customers));
    for (int i = 0; i < customers; ++i) s[size_t(i)] = can(i) ? (i % 3 == 0 ? 2.0 : 0.0) : kInfinity;
    in.service.push_back(std::move(s));
  }
  return in;
}

std::vector<int> identity(int n) {
  std::vector<int> v(static_cast<size_t>(n));
  std::iota(v.begin(), v.end(), 0);
  return v;
}

// Every split of every permutation into the vehicles' routes.
double brute_force(const VrpInstance& in) {
  std::vector<int> perm = identity(in.customers);
  double best = kInfinity;
  const int V = in.vehicles();
  do {
    // cut positions: V - 1 non-decreasing cuts in [0, n]
    std::vector<int> cuts(size_t(V - 1), 0);
    for (;;) {
      VrpRoutes r(static_cast<size_t>(V));
      int at = 0;
      for (int v = 0; v < V; ++v) {
        const int end = v + 1 < V ? cuts[size_t(v)] : in.customers;
        r[size_t(v)].assign(perm.begin() + at, perm.begin() + end);
        at = end;
      }
      const VrpCost c = vrp_cost(in, r);
      if (c.feasible) best = std::min(best, c.objective);
      int k = V - 2;
      while (k >= 0 && cuts[size_t(k)] == in.customers) --k;
      if (k < 0) break;
      ++cuts[size_t(k)];
      for (int j = k + 1; j < V - 1; ++j) cuts[size_t(j)] = cuts[size_t(k)];
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

TEST(VrpSearch, CheapestInsertionPlacesEveryServableCustomerWhereAllowed) {
  const VrpInstance in = random_instance(40, 4, 3);
  const VrpRoutes r = cheapest_insertion(in, VrpRoutes(4), identity(40));
  const VrpCost c = vrp_cost(in, r);
  EXPECT_EQ(c.dropped, 0);
  EXPECT_TRUE(c.feasible);
  for (int v = 0; v < 4; ++v)
    for (int n : r[size_t(v)]) EXPECT_TRUE(in.eligible(v, n)) << "customer " << n << " on vehicle " << v;
}

TEST(VrpSearch, NeverWorseThanItsStartAndRespectsCapabilities) {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const VrpInstance in = random_instance(60, 3, seed);
    // Starts: cheapest insertion, and a poor but feasible one (each customer on the first
    // vehicle that may take it, in index order).
    VrpRoutes poor(3);
    for (int c = 0; c < 60; ++c)
      for (int v = 0; v < 3; ++v)
        if (in.eligible(v, c)) {
          poor[size_t(v)].push_back(c);
          break;
        }
    for (const VrpRoutes& start : {cheapest_insertion(in, VrpRoutes(3), identity(60)), poor}) {
      GlsOptions o;
      o.max_evaluations = 20000;
      o.seed = seed;
      const VrpCost before = vrp_cost(in, start);
      const GlsResult res = guided_local_search(in, start, o);
      EXPECT_LE(res.cost.objective, before.objective + 1e-6) << "seed " << seed;
      EXPECT_NEAR(res.start_cost.objective, before.objective, 1e-6);
      EXPECT_TRUE(res.cost.feasible);
      EXPECT_EQ(res.cost.dropped, 0);
      EXPECT_LE(res.evaluations, o.max_evaluations);
      std::vector<int> seen;
      for (int v = 0; v < 3; ++v)
        for (int n : res.routes[size_t(v)]) {
          EXPECT_TRUE(in.eligible(v, n));
          seen.push_back(n);
        }
      std::sort(seen.begin(), seen.end());
      EXPECT_EQ(seen, identity(60));
    }
  }
}

TEST(VrpSearch, ImprovesTheCheapestInsertionAndIsDeterministicPerSeed) {
  const VrpInstance in = random_instance(80, 4, 9);
  const VrpRoutes start = cheapest_insertion(in, VrpRoutes(4), identity(80));
  GlsOptions o;
  o.max_evaluations = 200000;
  const GlsResult a = guided_local_search(in, start, o);
  const GlsResult b = guided_local_search(in, start, o);
  EXPECT_EQ(a.routes, b.routes);
  EXPECT_LT(a.cost.objective, 0.95 * a.start_cost.objective);
  EXPECT_GT(a.local_optima, 0);  // the budget outlasts the first descent: GLS penalties at work
  o.seed = 2;
  const GlsResult c = guided_local_search(in, start, o);
  EXPECT_LE(c.cost.objective, c.start_cost.objective);
}

TEST(VrpSearch, FindsTheOptimumOfTinyInstances) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const VrpInstance in = random_instance(7, 2, 100 + seed);
    const double optimum = brute_force(in);
    GlsOptions o;
    o.max_evaluations = 50000;
    o.seed = seed;
    const GlsResult res = guided_local_search(in, cheapest_insertion(in, VrpRoutes(2), identity(7)), o);
    EXPECT_NEAR(res.cost.objective, optimum, 1e-3 * optimum) << "seed " << seed;
  }
}

TEST(VrpSearch, TimeBudgetAloneEndsTheSearch) {
  const VrpInstance in = random_instance(60, 3, 4);
  GlsOptions o;
  o.time_budget_s = 0.02;
  o.clock = BudgetClock::kThreadCpu;
  const GlsResult res = guided_local_search(in, cheapest_insertion(in, VrpRoutes(3), identity(60)), o);
  EXPECT_LT(res.elapsed_s, 0.5);
  EXPECT_GT(res.evaluations, 0);
  EXPECT_LE(res.cost.objective, res.start_cost.objective);
}

TEST(VrpSearch, RejectsInconsistentStarts) {
  const VrpInstance in = random_instance(5, 2, 1);
  GlsOptions o;
  o.max_evaluations = 10;
  EXPECT_THROW(guided_local_search(in, VrpRoutes(3), o), std::invalid_argument);
  EXPECT_THROW(guided_local_search(in, VrpRoutes{{0, 1}, {1}}, o), std::invalid_argument);
  EXPECT_THROW(guided_local_search(in, VrpRoutes{{0, 9}, {}}, o), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::planning
