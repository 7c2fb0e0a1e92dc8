// One planning round on a synthetic high-level map the size of the paper's multi-building
// scene (about 1,550 m^2 of ground, three buildings, rubble) with 4 robots of 2 species
// (2 x SLUGCAT, 2 x MR1000), stage by stage, for every registered planner (the paper's
// method, its ablations and the comparison baselines), and the assignment agreement of two
// robots per planner. Single thread; times are the thread's CPU time, so a loaded machine
// does not inflate them.
// Usage: bench_planning_round [--rounds N] [--planner NAME]

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/highlevel/supervoxel.h"
#include "common/planning/planner_registry.h"

#include "tests/support/plan_agreement.h"
#include "tests/support/planning_scene.h"

using namespace hexplore;
using namespace hexplore::planning;

int main(int argc, char** argv) {
  int rounds = 5;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--planner") && i + 1 < argc) only = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--rounds N] [--planner NAME]\n", argv[0]);
      return 2;
    }
  }
  core::TeamConfig team;
  team.species = {core::builtin_slugcat(), core::builtin_mr1000()};
  team.robots = {{"slug1", "SLUGCAT", {1.5, 1.5, 0}, 0}, {"slug2", "SLUGCAT", {43.5, 33.5, 0}, 0},
                 {"mr1", "MR1000", {2.5, 33.5, 0}, 0}, {"mr2", "MR1000", {30.5, 15.5, 0}, 0}};
  PlannerContext ctx{capabilities_from(team), PlannerOptions::from(team.params)};
  ctx.options.cpu_clock = true;  // stage times and GA budget in thread CPU time (shared machine)

  highlevel::HighLevelMap map(highlevel::species_levels(team));
  map.apply(synthetic_scene(SyntheticSceneOptions{}));
  int ground = 0, facade = 0, ise = 0;
  for (const auto& [k, sv] : map.supervoxels()) {
    ground += sv.ground();
    facade += sv.facade();
    ise += !sv.covered;
  }
  std::printf("map: %zu supervoxels (%d ground, %d facade, %d ISE), %zu graph vertices, %zu edges\n", map.size(), ground,
              facade, ise, map.graph().vertex_count(), map.graph().edge_count());
  std::printf("team: 2 x SLUGCAT (level 2, 10 m), 2 x MR1000 (level 1, 27 m); GA %d x %d generations, budget %.3f s\n",
              ctx.options.ga_population, ctx.options.ga_max_generations, ctx.options.ga_time_budget_s);
  std::printf("median of %d rounds (planning robot slug1; the graph's distance cache is cold each round)\n\n", rounds);
  std::printf("%-11s %8s %8s %8s %8s %8s | %6s %8s %6s %9s %8s\n", "planner", "views", "cluster", "assign", "mnss",
              "total", "views", "clusters", "gens", "fitness", "route");

  const PlannerRegistry registry = PlannerRegistry::builtin();
  for (const auto& name : registry.names()) {
    if (!only.empty() && name != only) continue;
    auto planner = registry.create(name);
    planner->configure(ctx);
    planner->activate();
    std::vector<StageTimes> times;
    PlanResult last;
    for (int r = 0; r < rounds; ++r) {
      highlevel::HighLevelMap fresh(highlevel::species_levels(team));  // cold distance cache
      fresh.apply(synthetic_scene(SyntheticSceneOptions{}));
      PlanRequest req;
      req.map = &fresh;
      for (const auto& rc : team.robots) req.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
      req.self = 0;
      req.round = uint64_t(r);
      last = planner->plan(req);
      times.push_back(last.times);
    }
    auto median = [&](double StageTimes::*f) {
      std::vector<double> v;
      for (const auto& t : times) v.push_back(t.*f);
      std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
      return 1e3 * v[v.size() / 2];
    };
    std::printf("%-11s %6.1fms %6.1fms %6.1fms %6.1fms %6.1fms | %6d %8d %6d %9.1f %8zu\n", name.c_str(),
                median(&StageTimes::views_s), median(&StageTimes::clustering_s), median(&StageTimes::assignment_s),
                median(&StageTimes::mnss_s), median(&StageTimes::total_s), last.views, last.clusters, last.ga_generations,
                last.fitness, last.robots[0].route.size());
    if (!only.empty())
      std::printf("  view stage: %d facade targets, %d facade views, %d unobservable, %d composite ground, %d ground views, "
                  "%lld rays\n",
                  last.view_stats.facade_targets, last.view_stats.facade_views, last.view_stats.unobservable_facades,
                  last.view_stats.composite_ground, last.view_stats.ground_views, (long long)last.view_stats.rays_cast);
  }
  if (only.empty() || only == "hexplore") {
    // The assignment with and without the memetic local search, same generation budget and
    // no time budget (deterministic), on the same map.
    std::printf("\nhexplore assignment fitness (400 generations, no time budget):");
    for (bool memetic : {false, true}) {
      PlannerContext c = ctx;
      c.options.ga_memetic = memetic;
      c.options.ga_time_budget_s = 0.0;
      auto planner = registry.create("hexplore");
      planner->configure(c);
      highlevel::HighLevelMap fresh(highlevel::species_levels(team));
      fresh.apply(synthetic_scene(SyntheticSceneOptions{}));
      PlanRequest req;
      req.map = &fresh;
      for (const auto& rc : team.robots) req.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
      const PlanResult res = planner->plan(req);
      std::printf(" %s %.1f (%.1f ms)", memetic ? "memetic" : "plain-GA", res.fitness, 1e3 * res.times.assignment_s);
    }
    std::printf("\n");
  }
  {
    // Decentralised consistency, per planner: two robots plan from maps that differ slightly
    // (robot B has not yet received 5 % of the facade-ISE supervoxels, seen as covered),
    // first without any shared solution, then with both previous solutions shared as
    // reference candidates (planners that share no route ignore them).
    auto make_map = [&](double lag) {
      auto up = synthetic_scene(SyntheticSceneOptions{});
      hide_open_facades(up, lag);
      auto m = std::make_unique<highlevel::HighLevelMap>(highlevel::species_levels(team));
      m->apply(up);
      return m;
    };
    const auto map_a = make_map(0.0), map_b = make_map(0.05);
    PlannerContext c = ctx;
    c.options.ga_time_budget_s = 0.0;
    std::printf("\nassignment agreement between two robots whose maps differ by 5 %% of facade ISE "
                "(share of common clusters / views both give the same robot):\n");
    for (const auto& name : registry.names()) {
      if (!only.empty() && name != only) continue;
      auto pa = registry.create(name), pb = registry.create(name);
      pa->configure(c);
      pb->configure(c);
      PlanRequest ra, rb;
      ra.map = map_a.get();
      rb.map = map_b.get();
      for (const auto& rc : team.robots) ra.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
      rb.robots = ra.robots;
      ra.self = 0;
      rb.self = 2;
      const PlanResult a1 = pa->plan(ra), b1 = pb->plan(rb);
      if (pa->route_sharing() == RouteSharing::kNone) {
        std::printf("  %-11s %.2f (shares no route; clusters %d / %d)\n", name.c_str(), assignment_agreement(a1, b1), a1.clusters,
                    b1.clusters);
        continue;
      }
      ra.shared = rb.shared = {a1.as_reference("slug1"), b1.as_reference("mr1")};
      ra.round = rb.round = 1;
      const PlanResult a2 = pa->plan(ra), b2 = pb->plan(rb);
      std::printf("  %-11s %.2f without reference, %.2f with shared reference (clusters %d / %d)\n", name.c_str(),
                  assignment_agreement(a1, b1), assignment_agreement(a2, b2), a2.clusters, b2.clusters);
    }
  }
  return 0;
}
