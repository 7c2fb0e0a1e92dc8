#include "common/planning/mtsp/ga_solver.h"

#include <set>

#include <gtest/gtest.h>

#include "tests/planning/mtsp_fixtures.h"

namespace hexplore::planning {
namespace {

using testing::random_problem;

GaOptions deterministic(uint64_t seed, int generations, LocalSearchMode ls = LocalSearchMode::kNone) {
  GaOptions o;
  o.seed = seed;
  o.max_generations = generations;
  o.local_search = ls;
  return o;
}

void expect_valid(const MtspProblem& p, const std::vector<Route>& routes) {
  ASSERT_EQ(routes.size(), p.robots.size());
  std::set<int> seen;
  for (size_t r = 0; r < routes.size(); ++r)
    for (int c : routes[r]) {
      EXPECT_TRUE(seen.insert(c).second) << "city " << c << " visited twice";
      EXPECT_TRUE(p.eligible(int(r), c)) << "robot " << r << " cannot serve city " << c;
    }
  EXPECT_EQ(int(seen.size()), p.num_cities);
}

struct TinyCase {
  int cities;
  std::vector<int> robot_species;
  int num_species;
  RouteKind kind;
  bool labelled;
  FitnessWeights weights;
};

class TinyOptimum : public ::testing::TestWithParam<TinyCase> {};

// On tiny instances the GA (paper operators, generation budget) reaches the exhaustive optimum.
TEST_P(TinyOptimum, GaMatchesBruteForce) {
  const TinyCase& tc = GetParam();
  for (uint64_t instance = 1; instance <= 3; ++instance) {
    const MtspProblem p = random_problem(tc.cities, tc.robot_species, tc.num_species, tc.kind, 100 + instance, tc.labelled);
    const FitnessModel model(p, tc.weights);
    const GaResult exact = solve_brute_force(model);
    const GaResult ga = solve_ga(model, deterministic(7, 3000));
    expect_valid(p, ga.routes);
    EXPECT_NEAR(ga.breakdown.fitness, exact.breakdown.fitness, 1e-6 * exact.breakdown.fitness) << "instance " << instance;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Planning, TinyOptimum,
    ::testing::Values(TinyCase{8, {0, 0}, 1, RouteKind::kOpen, false, FitnessWeights::min_sum()},
                      TinyCase{8, {0, 0}, 1, RouteKind::kClosed, false, FitnessWeights::min_max()},
                      TinyCase{7, {0, 0, 0}, 1, RouteKind::kClosed, false, FitnessWeights::min_sum()},
                      TinyCase{8, {0, 1, 1}, 2, RouteKind::kOpen, true, FitnessWeights{1.0, 1.5, 0.0, 0.5}},
                      TinyCase{7, {0, 1}, 2, RouteKind::kOpen, true, FitnessWeights::min_max()}));

TEST(GaSolver, NeverWorseThanInitialBestAndNeverWorseWithMoreWork) {
  const MtspProblem p = random_problem(40, {0, 0, 1, 1}, 2, RouteKind::kOpen, 5, true);
  const FitnessModel model(p, FitnessWeights{1.0, 1.5, 0.0, 0.5});
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const GaResult r = solve_ga(model, deterministic(seed, 200));
    EXPECT_LE(r.breakdown.fitness, r.initial_best_fitness);
    EXPECT_TRUE(r.feasible);
    expect_valid(p, r.routes);
    const GaResult ls = solve_ga(model, deterministic(seed, 200, LocalSearchMode::kMemetic));
    EXPECT_LE(ls.breakdown.fitness, ls.initial_best_fitness);
    expect_valid(p, ls.routes);
  }
}

TEST(GaSolver, SameSeedSameRoutes) {
  const MtspProblem p = random_problem(30, {0, 1, 1}, 2, RouteKind::kOpen, 9, true);
  const FitnessModel model(p, FitnessWeights{1.0, 1.5, 0.0, 0.5});
  for (auto ls : {LocalSearchMode::kNone, LocalSearchMode::kMemetic}) {
    const GaResult a = solve_ga(model, deterministic(42, 150, ls));
    const GaResult b = solve_ga(model, deterministic(42, 150, ls));
    EXPECT_EQ(a.routes, b.routes);
    EXPECT_EQ(a.breakdown.fitness, b.breakdown.fitness);
  }
  const GaResult c = solve_ga(model, deterministic(43, 150));
  EXPECT_EQ(c.generations, 150);
}

TEST(GaSolver, PrivateCitiesOnlyGoToTheirSpecies) {
  MtspProblem p = random_problem(20, {0, 1}, 2, RouteKind::kOpen, 11, false);
  p.city_species.assign(20, kPublic);
  for (int c = 0; c < 20; c += 3) p.city_species[size_t(c)] = 1;
  for (int c = 1; c < 20; c += 5) p.city_species[size_t(c)] = 0;
  const FitnessModel model(p, FitnessWeights::min_sum());
  const GaResult r = solve_ga(model, deterministic(3, 100));
  expect_valid(p, r.routes);
  EXPECT_TRUE(r.feasible);
}

// A city reachable only by one robot (disconnected graph for the other) is never given to
// the other robot, even though both share the species.
TEST(GaSolver, UnreachableCitiesAreAvoided) {
  MtspProblem p = random_problem(12, {0, 0}, 1, RouteKind::kOpen, 13, false);
  CostMatrix m = p.travel[0];
  const int robot1 = p.depot(1);
  for (int c = 0; c < 4; ++c) {
    m.set(robot1, c, kInfinity);
    m.set(c, robot1, kInfinity);
    for (int d = 4; d < 12; ++d) m.set(c, d, kInfinity), m.set(d, c, kInfinity);
  }
  p.travel[0] = m;
  const FitnessModel model(p, FitnessWeights::min_max());
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const GaResult r = solve_ga(model, deterministic(seed, 300, LocalSearchMode::kFinal));
    EXPECT_TRUE(r.feasible) << "seed " << seed;
    for (int c : r.routes[1]) EXPECT_GE(c, 4);
  }
}

TEST(GaSolver, MinCitiesPerRobotIsKept) {
  MtspProblem p = random_problem(15, {0, 0, 0, 0}, 1, RouteKind::kClosed, 17, false);
  p.min_cities_per_robot = 1;
  const FitnessModel model(p, FitnessWeights::min_sum());
  const GaResult r = solve_ga(model, deterministic(5, 300, LocalSearchMode::kMemetic));
  for (const auto& route : r.routes) EXPECT_GE(route.size(), 1u);
}

TEST(GaSolver, InvalidProblemIsRejected) {
  MtspProblem p = random_problem(5, {0}, 2, RouteKind::kOpen, 1, false);
  p.city_species.assign(5, 1);  // species 1 has no robot
  const FitnessModel model(p, FitnessWeights::min_sum());
  EXPECT_THROW(solve_ga(model, deterministic(1, 10)), std::invalid_argument);
}

TEST(LocalSearch, NeverWorsensAndImprovesRandomRoutes) {
  const MtspProblem p = random_problem(50, {0, 0, 0}, 1, RouteKind::kClosed, 21, false);
  const FitnessModel model(p, FitnessWeights::min_sum());
  std::vector<Route> routes(3);
  for (int c = 0; c < 50; ++c) routes[size_t(c % 3)].push_back(c);
  const double before = model.fitness(routes);
  const LocalSearchStats s = local_search(model, routes);
  EXPECT_LT(s.fitness_after, before);
  EXPECT_NEAR(model.fitness(routes), s.fitness_after, 1e-6 * before);
  expect_valid(p, routes);
}

TEST(Fitness, ReferenceTermUsesSegmentsAndPositionDecay) {
  MtspProblem p = random_problem(3, {0}, 1, RouteKind::kOpen, 1, false);
  p.positions[0] = {0, 1, 0};
  p.positions[1] = {5, 2, 0};
  p.positions[2] = {20, 0, 0};
  const std::vector<std::vector<Eigen::Vector3d>> ref = {{{0, 0, 0}, {10, 0, 0}}};
  const FitnessModel model(p, FitnessWeights{0.0, 0.0, 1.0, 0.5}, ref);
  const double expected = std::exp(-0.5) * 1.0 + std::exp(-1.0) * 2.0 + std::exp(-1.5) * 10.0;
  EXPECT_NEAR(model.reference_distance(0, {0, 1, 2}), expected, 1e-9);
  EXPECT_NEAR(point_segment_distance({5, 3, 0}, {0, 0, 0}, {10, 0, 0}), 3.0, 1e-12);
  EXPECT_NEAR(point_segment_distance({-3, 4, 0}, {0, 0, 0}, {10, 0, 0}), 5.0, 1e-12);
}

// Against the whole polyline a route that runs the reference backwards is as close as one that
// follows it; with a window the i-th city is matched against the reference's first i + window
// + 1 segments only, so turning round costs and following costs nothing.
TEST(Fitness, AWindowedReferenceTellsARouteThatRunsItBackwards) {
  MtspProblem p = random_problem(4, {0}, 1, RouteKind::kOpen, 1, false);
  for (int c = 0; c < 4; ++c) p.positions[size_t(c)] = {10.0 * c, 0, 0};  // cities on the reference
  const std::vector<std::vector<Eigen::Vector3d>> ref = {{{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}}};
  const Route forwards = {0, 1, 2, 3}, backwards = {3, 2, 1, 0};
  const FitnessModel literal(p, FitnessWeights{0.0, 0.0, 1.0, 0.5, -1}, ref);
  EXPECT_NEAR(literal.reference_distance(0, forwards), 0.0, 1e-12);
  EXPECT_NEAR(literal.reference_distance(0, backwards), 0.0, 1e-12);
  const FitnessModel windowed(p, FitnessWeights{0.0, 0.0, 1.0, 0.5, 0}, ref);
  EXPECT_NEAR(windowed.reference_distance(0, forwards), 0.0, 1e-12);
  // City 3 first is 20 m past segment 0; city 2 second ends segment 1, and so on.
  EXPECT_NEAR(windowed.reference_distance(0, backwards), std::exp(-0.5) * 20.0, 1e-9);
  const FitnessModel window1(p, FitnessWeights{0.0, 0.0, 1.0, 0.5, 1}, ref);
  EXPECT_NEAR(window1.reference_distance(0, {1, 2, 3}), 0.0, 1e-12) << "a city done since is skipped freely";
  EXPECT_NEAR(window1.reference_distance(0, backwards), std::exp(-0.5) * 10.0, 1e-9);
}

// With a reference the GA prefers the solution that follows it when costs tie.
TEST(Fitness, ReferencePullsTowardsReferenceAssignment) {
  MtspProblem p;
  p.num_cities = 2;
  p.robots = {{0}, {0}};
  p.positions = {{10, 0, 0}, {-10, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  CostMatrix m(4);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) m.set(a, b, (p.positions[size_t(a)] - p.positions[size_t(b)]).norm());
  p.travel.push_back(m);
  const std::vector<std::vector<Eigen::Vector3d>> ref = {{{0, 0, 0}, {-10, 0, 0}}, {{0, 0, 0}, {10, 0, 0}}};
  const FitnessModel model(p, FitnessWeights{1.0, 1.5, 3.0, 0.5}, ref);
  const GaResult r = solve_ga(model, deterministic(1, 50));
  EXPECT_EQ(r.routes[0], Route{1});
  EXPECT_EQ(r.routes[1], Route{0});
}

}  // namespace
}  // namespace hexplore::planning
