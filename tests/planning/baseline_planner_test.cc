// The comparison baselines (BASELINES.md) as planners: each view or cluster goes to a robot
// whose species matches and can reach it; MROMT+ and TSPGA+ are deterministic on identical
// input (also across robots and map histories); MDVRP+'s search never ends worse than its
// warm start; TSPGA+'s greedy takes the largest utility increment.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "common/planning/candidate_views.h"
#include "common/planning/clustering.h"
#include "common/planning/executable_path.h"
#include "common/planning/graph_tour.h"
#include "common/planning/labels.h"
#include "common/planning/lloyd_clusters.h"
#include "common/planning/mdvrp_planner.h"
#include "common/planning/mnss.h"
#include "common/planning/mromt_planner.h"
#include "common/planning/robot_vertex.h"
#include "common/planning/round_inputs.h"
#include "common/planning/utility_greedy.h"
#include "common/planning/view_costs.h"
#include "tests/planning/planner_fixture.h"

namespace hexplore::planning {
namespace {

using testing::PlannerFixture;

const char* const kBaselines[] = {"mdvrp+", "mromt+", "tspga+"};

// The planning robot's first view can be driven to (the service makes the path from it).
void expect_route_drivable(const PlannerFixture& f, const PlanRequest& req, const PlanResult& res, const std::string& name) {
  const auto& me = req.robots[size_t(req.self)];
  ASSERT_FALSE(res.robots[size_t(req.self)].route.empty()) << name;
  EXPECT_TRUE(executable_path(f.map.graph(), me.position, me.species, res.robots[size_t(req.self)].route.front()).valid)
      << name;
}

TEST(Baselines, RegisteredAndNamed) {
  const PlannerRegistry reg = PlannerRegistry::builtin();
  for (const char* name : kBaselines) {
    ASSERT_TRUE(reg.contains(name)) << name;
    EXPECT_EQ(reg.create(name)->name(), name);
  }
  EXPECT_EQ(reg.create("mdvrp+")->route_sharing(), RouteSharing::kEverySolution);
  EXPECT_EQ(reg.create("mromt+")->route_sharing(), RouteSharing::kNone);
  EXPECT_EQ(reg.create("tspga+")->route_sharing(), RouteSharing::kNone);
  EXPECT_EQ(reg.create("hexplore")->route_sharing(), RouteSharing::kReferenceOnly);
  EXPECT_EQ(reg.create("no-assign")->route_sharing(), RouteSharing::kReferenceOnly);
}

TEST(Baselines, MdvrpGivesEveryViewOnceToAMatchingRobotThatReachesIt) {
  PlannerFixture f;
  const PlanRequest req = f.request(2);
  const PlanResult res = f.planner("mdvrp+")->plan(req);
  const RoundInputs in = prepare_round(req, f.caps, f.options);
  std::map<uint64_t, const TaskView*> by_key;
  for (const auto& v : in.views) by_key[v.key] = &v;
  std::set<uint64_t> assigned;
  for (size_t r = 0; r < res.robots.size(); ++r) {
    const int k = req.robots[r].species;
    const auto start = robot_vertex(f.map.graph(), req.robots[r].position, k);
    ASSERT_TRUE(start);
    for (uint64_t key : res.robots[r].cluster_ids) {
      ASSERT_TRUE(by_key.count(key)) << "unknown view " << key;
      const TaskView& v = *by_key[key];
      EXPECT_TRUE(assigned.insert(key).second) << "view " << key << " twice";
      EXPECT_TRUE(matches(v.observation_requirement, v.traversal_requirement, f.caps.species[size_t(k)]))
          << "view " << key << " to robot " << r;
      EXPECT_TRUE(in.reachable[size_t(k)].count(v.ground_key));
      EXPECT_TRUE(std::isfinite(f.map.graph().dist(*start, v.ground_key, k)));
    }
    EXPECT_GT(res.robots[r].cost_s, 0.0);
    EXPECT_GT(res.robots[r].route_length_m, 0.0);
  }
  EXPECT_EQ(int(assigned.size()), res.open_views);
  EXPECT_EQ(res.open_views + res.dropped_clusters, res.views);
  EXPECT_GT(res.views, 0);
  // The executed route is the planning robot's part of the team solution, in order.
  std::vector<uint64_t> route;
  for (const auto& v : res.robots[2].route) route.push_back(v.key);
  EXPECT_EQ(route, res.robots[2].cluster_ids);
  expect_route_drivable(f, req, res, "mdvrp+");
  // The wheeled robots stay west of the rubble band.
  for (size_t r = 2; r < 4; ++r)
    for (const auto& c : res.robots[r].cluster_centers) EXPECT_LT(c.x(), 24.0);
}

TEST(Baselines, MdvrpSearchNeverEndsWorseThanItsWarmStart) {
  PlannerFixture f;
  auto planner = f.planner("mdvrp+");
  PlanRequest req = f.request(0);
  const PlanResult first = planner->plan(req);
  // Same map next round: the shared solution projects onto itself, so the warm start's
  // objective is the first round's; another robot's seed may not make it worse.
  for (int self : {0, 1, 3}) {
    PlanRequest next = f.request(self);
    next.round = 1;
    next.shared = {first.as_reference("slug1")};
    const PlanResult again = f.planner("mdvrp+")->plan(next);
    EXPECT_LE(again.fitness, first.fitness + 1e-6 * first.fitness) << "self " << self;
    ASSERT_TRUE(again.agreement.has_value());
    EXPECT_GE(*again.agreement, 0.6) << "self " << self;
  }
  // A shared solution from a map that has since lost views still projects (removed views
  // dropped, the rest kept in order) and the result still serves every view.
  PlanRequest partial = f.request(0);
  partial.round = 2;
  ReferenceSolution stale = first.as_reference("mr2");
  for (auto& route : stale.routes)
    if (route.cluster_ids.size() > 4) route.cluster_ids.resize(route.cluster_ids.size() / 2);
  stale.routes.front().cluster_ids.push_back(12345);  // a view that no longer exists
  partial.shared = {stale};
  const PlanResult res = f.planner("mdvrp+")->plan(partial);
  size_t served = 0;
  for (const auto& r : res.robots) served += r.cluster_ids.size();
  EXPECT_EQ(int(served), res.open_views);
}

TEST(Baselines, MdvrpRobotsDivergeOnlyThroughTheirSeeds) {
  // The move order is seeded per robot and round (a time-limited solver's randomness): the
  // same robot and round give the same solution, and a shared warm start keeps robots close.
  PlannerFixture f;
  const PlanResult a = f.planner("mdvrp+")->plan(f.request(1));
  const PlanResult b = f.planner("mdvrp+")->plan(f.request(1));
  for (size_t r = 0; r < a.robots.size(); ++r) EXPECT_EQ(a.robots[r].cluster_ids, b.robots[r].cluster_ids);
  EXPECT_EQ(a.fitness, b.fitness);
}

// Plans with every robot as the planning one (separate instances), and on a map that was fed
// in another order: every run gives the same team solution, and each robot's executed route
// is its part of it.
void expect_deterministic(const std::string& name) {
  PlannerFixture f;
  const auto other = f.reversed_map();
  std::vector<PlanResult> runs;
  for (int self = 0; self < 4; ++self) {
    runs.push_back(f.planner(name)->plan(f.request(self)));
    runs.push_back(f.planner(name)->plan(f.request(self, other.get())));
  }
  const PlanResult& ref = runs.front();
  for (const auto& run : runs) {
    ASSERT_EQ(run.robots.size(), ref.robots.size());
    EXPECT_EQ(run.views, ref.views) << name;
    EXPECT_EQ(run.clusters, ref.clusters) << name;
    EXPECT_EQ(run.open_views, ref.open_views) << name;
    for (size_t r = 0; r < ref.robots.size(); ++r) {
      EXPECT_EQ(run.robots[r].cluster_ids, ref.robots[r].cluster_ids) << name << " robot " << r;
      EXPECT_NEAR(run.robots[r].cost_s, ref.robots[r].cost_s, 1e-6) << name << " robot " << r;
    }
  }
  // Each robot's route as it planned it, from either map history, is identical.
  for (int self = 0; self < 4; ++self) {
    const auto& x = runs[size_t(2 * self)].robots[size_t(self)].route;
    const auto& y = runs[size_t(2 * self + 1)].robots[size_t(self)].route;
    ASSERT_EQ(x.size(), y.size()) << name << " robot " << self;
    for (size_t i = 0; i < x.size(); ++i) {
      EXPECT_EQ(x[i].ground_key, y[i].ground_key) << name << " robot " << self << " view " << i;
      EXPECT_EQ(x[i].targets, y[i].targets) << name << " robot " << self << " view " << i;
    }
  }
}

TEST(Baselines, MromtIsDeterministicOnEveryRobot) { expect_deterministic("mromt+"); }
TEST(Baselines, TspgaIsDeterministicOnEveryRobot) { expect_deterministic("tspga+"); }

TEST(Baselines, MromtRoutesOnlyHoldViewsTheRobotCanTakeAndShareNoTarget) {
  PlannerFixture f;
  const RoundInputs in = prepare_round(f.request(0), f.caps, f.options);
  std::set<uint64_t> task_targets;
  for (const auto& v : in.views) task_targets.insert(v.targets.begin(), v.targets.end());
  std::set<uint64_t> seen;
  size_t routed = 0;
  int robots_with_work = 0;
  for (int self = 0; self < 4; ++self) {
    const PlanRequest req = f.request(self);
    const PlanResult res = f.planner("mromt+")->plan(req);
    const auto& me = req.robots[size_t(self)];
    const auto start = robot_vertex(f.map.graph(), me.position, me.species);
    ASSERT_TRUE(start);
    EXPECT_LE(res.robots[size_t(self)].route.size(), size_t(kMromtViewsPerRobot) * 4);
    robots_with_work += res.robots[size_t(self)].route.empty() ? 0 : 1;
    for (const auto& v : res.robots[size_t(self)].route) {
      ++routed;
      EXPECT_TRUE(matches(v.observation_requirement, v.traversal_requirement, f.caps.species[size_t(me.species)]));
      EXPECT_TRUE(in.reachable[size_t(me.species)].count(v.ground_key));
      EXPECT_TRUE(std::isfinite(f.map.graph().dist(*start, v.ground_key, me.species)));
      ASSERT_FALSE(v.targets.empty());
      for (uint64_t t : v.targets) {
        EXPECT_TRUE(task_targets.count(t)) << "target " << t << " is no task view's";
        EXPECT_TRUE(seen.insert(t).second) << "target " << t << " in two routes";  // co-visibility pruning
      }
    }
    if (self == 0) {
      EXPECT_GT(res.open_views, 0);
      EXPECT_LT(res.open_views, res.views);  // merged views: fewer than the task views
    }
  }
  EXPECT_GT(robots_with_work, 1);
  EXPECT_LE(routed, size_t(kMromtViewsPerRobot) * 4);  // the round's batch
}

TEST(Baselines, TspgaClustersGoToRobotsOfTheirLabelThatReachThem) {
  PlannerFixture f;
  const PlanRequest req = f.request(1);
  const PlanResult res = f.planner("tspga+")->plan(req);
  const RoundInputs in = prepare_round(req, f.caps, f.options);
  const auto clusters = cluster_views(in.views, f.options.eta_r_m);
  std::map<uint64_t, const TaskCluster*> by_id;
  for (const auto& c : clusters) by_id[c.id] = &c;
  std::set<uint64_t> assigned;
  for (size_t r = 0; r < res.robots.size(); ++r) {
    const int k = req.robots[r].species;
    const auto start = robot_vertex(f.map.graph(), req.robots[r].position, k);
    ASSERT_TRUE(start);
    for (uint64_t id : res.robots[r].cluster_ids) {
      const TaskCluster* c = by_id.at(id);
      EXPECT_TRUE(assigned.insert(id).second);
      EXPECT_TRUE(c->label == kPublic || c->label == k) << "cluster " << id << " to robot " << r;
      for (int v : c->views) EXPECT_TRUE(std::isfinite(f.map.graph().dist(*start, in.views[size_t(v)].ground_key, k)));
    }
  }
  EXPECT_EQ(int(assigned.size()) + res.dropped_clusters, res.clusters);
  // Inside its clusters the robot visits every view (no merging).
  size_t views_of_mine = 0;
  for (uint64_t id : res.robots[1].cluster_ids) views_of_mine += by_id.at(id)->views.size();
  EXPECT_EQ(res.robots[1].route.size(), views_of_mine);
  expect_route_drivable(f, req, res, "tspga+");
}

// --- TSPGA+'s greedy --------------------------------------------------------------------

// Three cities on a line x = 10, 20, 60 m and two robots at x = 0 and x = 70 (one species,
// 1 m/s, no execution time).
MtspProblem line_problem() {
  const std::vector<double> x = {10, 20, 60, 0, 70};
  MtspProblem p;
  p.num_cities = 3;
  p.robots = {{0}, {0}};
  CostMatrix m(5, kInfinity);
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 3; ++b) m.set(a, b, std::abs(x[size_t(a)] - x[size_t(b)]));
  p.travel = {m};
  return p;
}

TEST(UtilityGreedy, TakesTheLargestUtilityIncrement) {
  const MtspProblem p = line_problem();
  const double lambda = std::log(2.0) / 30.0;
  // City 0 is nearest robot 0 but little worth; city 1 just beyond it holds a lot.
  const std::vector<double> gain = {1.0, 10.0, 3.0};
  const GreedyInsertion first = best_insertion(p, {{}, {}}, {0, 0, 0}, gain, lambda);
  EXPECT_EQ(first.robot, 0);
  EXPECT_EQ(first.city, 1);
  EXPECT_NEAR(first.increment, 10.0 * std::exp(-lambda * 20.0), 1e-12);
  // Brute force over every (robot, city) at its cheapest position, after the first step:
  // the greedy's choice has the largest increase of that robot's utility.
  std::vector<Route> routes = {{1}, {}};
  std::vector<char> assigned = {0, 1, 0};
  const GreedyInsertion step = best_insertion(p, routes, assigned, gain, lambda);
  double best = -kInfinity;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) {
      if (assigned[size_t(c)]) continue;
      size_t at = 0;
      double added = kInfinity;
      for (size_t i = 0; i <= routes[size_t(r)].size(); ++i) {
        Route with = routes[size_t(r)];
        with.insert(with.begin() + long(i), c);
        const double d = route_cost(p, r, with) - route_cost(p, r, routes[size_t(r)]);
        if (d < added) added = d, at = i;
      }
      Route with = routes[size_t(r)];
      with.insert(with.begin() + long(at), c);
      const double inc = route_utility(p, r, with, gain, lambda) - route_utility(p, r, routes[size_t(r)], gain, lambda);
      best = std::max(best, inc);
      if (r == step.robot && c == step.city) {
        EXPECT_NEAR(step.increment, inc, 1e-12);
        EXPECT_EQ(step.position, int(at));
      }
    }
  EXPECT_NEAR(step.increment, best, 1e-12);
  // City 2 goes to robot 1 (10 m away) rather than robot 0 (40 m beyond its route).
  EXPECT_EQ(step.robot, 1);
  EXPECT_EQ(step.city, 2);
  // The whole allocation: robot 0 takes cities 0 and 1 (in the cheaper order 0, 1), robot 1 city 2.
  const auto all = greedy_allocation(p, gain, lambda);
  EXPECT_EQ(all[0], (Route{0, 1}));
  EXPECT_EQ(all[1], (Route{2}));
}

TEST(UtilityGreedy, TwoOptRemovesACrossing) {
  const MtspProblem p = line_problem();
  Route r = {1, 0, 2};  // 20, 10, 60 from 0: 20 + 10 + 50 = 80; best 0, 1, 2: 60
  two_opt_route(p, 0, r);
  EXPECT_EQ(r, (Route{0, 1, 2}));
}

// --- MROMT+'s pieces --------------------------------------------------------------------

TEST(MromtPieces, CandidatesSeeOnlyTaskViewTargetsAndCoverEachOfThem) {
  PlannerFixture f;
  const RoundInputs in = prepare_round(f.request(0), f.caps, f.options);
  const auto cands = candidate_views(*in.context, in.views, f.caps, f.options, f.options.eta_r_m, in.reachable);
  std::set<uint64_t> task_targets, seen;
  for (const auto& v : in.views) task_targets.insert(v.targets.begin(), v.targets.end());
  int made = 0;
  for (const auto& c : cands) {
    EXPECT_NE(c.species_mask, 0);
    made += c.task_view ? 0 : 1;
    EXPECT_TRUE(std::is_sorted(c.view.targets.begin(), c.view.targets.end()));
    for (uint64_t t : c.view.targets) {
      EXPECT_TRUE(task_targets.count(t));
      seen.insert(t);
    }
    if (!c.task_view) {  // a candidate stands on ground some robot reaches
      EXPECT_TRUE(in.reachable[0].count(c.view.ground_key) || in.reachable[1].count(c.view.ground_key));
    }
  }
  EXPECT_GT(made, 0);
  EXPECT_EQ(seen, task_targets);  // every target has a candidate (at least its own task view)
}

TEST(MromtPieces, LloydSplitsWideClustersAndRespectsCapabilities) {
  PlannerFixture f;
  const auto& graph = f.map.graph();
  // Views on open ground in two groups 20 m apart; the west group's first view only the
  // wheeled species may take.
  std::vector<TaskView> views;
  std::vector<int> masks;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(2.5, 16.5, 0), Eigen::Vector3d(3.5, 17.5, 0),
                                  Eigen::Vector3d(22.5, 16.5, 0), Eigen::Vector3d(21.5, 17.5, 0)}) {
    TaskView v;
    v.ground_key = *graph.nearest(p, 1);
    v.key = v.ground_key;
    v.position = *graph.position(v.ground_key);
    views.push_back(v);
    masks.push_back(views.size() == 1 ? 0b10 : 0b11);
  }
  const RoundInputs in = prepare_round(f.request(0), f.caps, f.options);
  const std::vector<LloydSeed> seeds = {{0, *robot_vertex(graph, {1.5, 1.5, 0}, 0)},
                                        {1, *robot_vertex(graph, {1.5, 18.5, 0}, 1)}};
  const auto clusters = capability_lloyd(graph, views, masks, seeds, in.reachable, {0.4, 0.5}, {5.0, 10});
  ASSERT_GE(clusters.size(), 2u);
  std::set<int> all;
  for (const auto& c : clusters) {
    for (int m : c.members) {
      all.insert(m);
      EXPECT_TRUE(masks[size_t(m)] & (1 << c.species));
      EXPECT_LE((views[size_t(m)].position - c.centre).norm(), 5.0 + 1.5);
    }
    EXPECT_TRUE(in.reachable[size_t(c.species)].count(c.centre_vertex));
  }
  EXPECT_EQ(all.size(), views.size());
}

TEST(MromtPieces, GraphTourVisitsStopsInTheirOrderAlongALine) {
  PlannerFixture f;
  const auto& graph = f.map.graph();
  std::vector<uint64_t> stops;
  for (double x : {20.5, 4.5, 12.5, 8.5}) stops.push_back(*graph.nearest({x, 16.5, 0}, 0));
  const GraphTour t = graph_tour(graph, *graph.nearest({1.5, 16.5, 0}, 0), stops, 0);
  EXPECT_EQ(t.order, (std::vector<int>{1, 3, 2, 0}));
  EXPECT_NEAR(t.length_m, 19.0, 0.5);
}

// Two rows of ground 2 m apart with a wall between them, joined only at x = 10 (a door):
// views alternate between the rows along x. Euclidean order zigzags through the wall; the
// graph order works along one row, through the door, and back along the other.
TEST(GraphTour, ViewsOnBothSidesOfAWallAreVisitedOneSideAtATime) {
  highlevel::TopologyGraph graph({1});
  auto key = [](int row, int x) { return uint64_t(100 * row + x + 1); };
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x <= 10; ++x) {
      graph.upsert_vertex(key(row, x), {double(x), 2.0 * row, 0.0}, 1);
      if (x > 0) graph.upsert_edge(key(row, x - 1), key(row, x), 1.0);
    }
  graph.upsert_edge(key(0, 10), key(1, 10), 2.0);
  auto view = [&](int row, int x) {
    TaskView v;
    v.key = v.ground_key = key(row, x);
    v.position = {double(x), 2.0 * row, 0.0};
    return v;
  };
  const std::vector<TaskView> views = {view(1, 3), view(0, 2), view(1, 7), view(0, 6)};
  auto keys = [](const std::vector<TaskView>& vs) {
    std::vector<uint64_t> k;
    for (const auto& v : vs) k.push_back(v.key);
    return k;
  };
  // Euclidean: row 0 x=2, row 1 x=3, row 0 x=6, row 1 x=7 -- three crossings of the wall.
  EXPECT_EQ(keys(order_views(views, {0, 0, 0}, std::nullopt)), (std::vector<uint64_t>{key(0, 2), key(1, 3), key(0, 6), key(1, 7)}));
  const auto on_graph = order_views_on_graph(graph, key(0, 0), views, 0);
  EXPECT_EQ(keys(on_graph), (std::vector<uint64_t>{key(0, 2), key(0, 6), key(1, 7), key(1, 3)}));
  // Towards an end on row 0 behind the start, row 1 first costs the same door trip but ends
  // nearer: the end leg counts.
  const auto towards_end = order_views_on_graph(graph, key(1, 0), views, 0, key(0, 0));
  EXPECT_EQ(keys(towards_end), (std::vector<uint64_t>{key(1, 3), key(1, 7), key(0, 6), key(0, 2)}));
  EXPECT_NEAR(graph_tour(graph, key(1, 0), {key(1, 3), key(1, 7), key(0, 6), key(0, 2)}, 0, key(0, 0)).length_m,
              10.0 + 2.0 + 10.0, 1e-9);
}

}  // namespace
}  // namespace hexplore::planning

