// How a planning round's cost grows with the team and with the work (issue "Scale"): the
// hexplore planner on a synthetic campus-sized high-level map (100 m x 100 m of ground, eight
// buildings with 7-10 m of wall, rubble the QUADRUPED and SLUGCAT cross and masonry only the
// SLUGCAT crosses), with the team file defaults (GA 64 x 400 generations in a 50 ms budget).
//  1. Teams of 2, 4, 8 and 16 robots of three species, interleaved as in campus-16.yaml
//     (QUADRUPED, SLUGCAT at traversal level 3, MR1000), starting 6 m apart along the south
//     edge: each stage's mean, the round's mean and p95, GA generations reached, and how far
//     two robots' assignments agree when their maps differ by 5 % of the open facades (without
//     and with both previous solutions shared as references).
//  2. Sixteen robots, the share of open supervoxels swept: round time against clusters and
//     views, and the growth exponent between the smallest and the largest point.
// Single thread; times are the thread's CPU time (a loaded machine inflates them less than
// wall time, but a busy sibling hyperthread still does: compare runs of one machine state).
// Usage: bench_planning_scale [--rounds N] [--csv DIR]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/planning/planner_registry.h"

#include "tests/support/plan_agreement.h"
#include "tests/support/planning_scene.h"

using namespace hexplore;
using namespace hexplore::planning;

namespace {

// The synthetic campus; `open_share`: the share of supervoxels not yet covered.
SyntheticSceneOptions campus(double open_share) {
  SyntheticSceneOptions o;
  o.width_cells = 100;
  o.depth_cells = 100;
  o.buildings = {{8, 10, 30, 24, 7},  {40, 8, 62, 20, 10},  {72, 10, 92, 28, 7},  {10, 40, 28, 62, 10},
                 {42, 38, 60, 60, 7}, {70, 44, 92, 66, 10}, {20, 74, 44, 92, 7}, {58, 76, 86, 94, 10}};
  o.rubble = {Eigen::Vector4i(32, 28, 40, 36), Eigen::Vector4i(62, 66, 70, 74), Eigen::Vector4i(90, 80, 99, 92)};
  o.masonry = {Eigen::Vector4i(0, 66, 8, 74), Eigen::Vector4i(46, 64, 56, 70)};
  o.covered_fraction = 1.0 - open_share;
  return o;
}

// The first `n` of the campus team of sixteen.
core::TeamConfig campus_team(int n) {
  core::TeamConfig team;
  core::SpeciesConfig slugcat = core::builtin_slugcat();
  slugcat.traversal_level = 3;
  team.species = {slugcat, core::builtin_quadruped(), core::builtin_mr1000()};
  const char* species[] = {"QUADRUPED", "SLUGCAT", "MR1000"};
  for (int i = 0; i < n; ++i)
    team.robots.push_back({std::string(species[i % 3]) + std::to_string(i + 1), species[i % 3], {5.5 + 6.0 * i, 1.5, 0}, 0});
  return team;
}

std::unique_ptr<highlevel::HighLevelMap> make_map(const core::TeamConfig& team, double open_share, double lag = 0.0) {
  auto up = synthetic_scene(campus(open_share));
  hide_open_facades(up, lag);
  auto map = std::make_unique<highlevel::HighLevelMap>(highlevel::species_levels(team));
  map->apply(up);
  return map;
}

PlanRequest request(const core::TeamConfig& team, const highlevel::HighLevelMap& map, size_t self, uint64_t round) {
  PlanRequest req;
  req.map = &map;
  for (const auto& rc : team.robots) req.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
  req.self = self;
  req.round = round;
  return req;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}

double p95(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[std::min(v.size() - 1, size_t(std::ceil(0.95 * double(v.size()))) - 1)];
}

struct Rounds {
  std::vector<double> views, clustering, assignment, mnss, total, generations, searches;
  int view_count = 0, clusters = 0;
};

// `rounds` rounds of `n` robots planning in turn, each on a fresh map (a cold distance cache).
Rounds run_rounds(const PlannerRegistry& registry, const core::TeamConfig& team, double open_share, int rounds) {
  PlannerContext ctx{capabilities_from(team), PlannerOptions::from(team.params)};
  ctx.options.cpu_clock = true;
  auto planner = registry.create("hexplore");
  planner->configure(ctx);
  planner->activate();
  Rounds out;
  for (int r = 0; r < rounds; ++r) {
    const auto map = make_map(team, open_share);
    const PlanResult res = planner->plan(request(team, *map, size_t(r) % team.robots.size(), uint64_t(r)));
    out.views.push_back(1e3 * res.times.views_s);
    out.clustering.push_back(1e3 * res.times.clustering_s);
    out.assignment.push_back(1e3 * res.times.assignment_s);
    out.mnss.push_back(1e3 * res.times.mnss_s);
    out.total.push_back(1e3 * res.times.total_s);
    out.generations.push_back(res.ga_generations);
    // Every full Dijkstra the round ran stays cached on the round's fresh graph (4,096 at most).
    out.searches.push_back(double(map->graph().cached_sources()));
    out.view_count = res.views;
    out.clusters = res.clusters;
  }
  return out;
}

// Agreement of robots 0 and 1 whose maps differ by 5 % of the open facades, without and then
// with both first solutions shared as reference routes (the paper's consistency mechanism).
std::pair<double, double> agreement(const PlannerRegistry& registry, const core::TeamConfig& team, double open_share) {
  PlannerContext ctx{capabilities_from(team), PlannerOptions::from(team.params)};
  ctx.options.ga_time_budget_s = 0.0;  // deterministic: generations, not CPU time
  auto pa = registry.create("hexplore"), pb = registry.create("hexplore");
  pa->configure(ctx);
  pb->configure(ctx);
  const auto map_a = make_map(team, open_share), map_b = make_map(team, open_share, 0.05);
  PlanRequest ra = request(team, *map_a, 0, 0), rb = request(team, *map_b, 1, 0);
  const PlanResult a1 = pa->plan(ra), b1 = pb->plan(rb);
  ra.shared = rb.shared = {a1.as_reference(team.robots[0].id), b1.as_reference(team.robots[1].id)};
  ra.round = rb.round = 1;
  const PlanResult a2 = pa->plan(ra), b2 = pb->plan(rb);
  return {assignment_agreement(a1, b1), assignment_agreement(a2, b2)};
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 8;
  std::string csv_dir;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv_dir = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--rounds N] [--csv DIR]\n", argv[0]);
      return 2;
    }
  }
  const PlannerRegistry registry = PlannerRegistry::builtin();
  const double team_open_share = 0.1;  // mid-mission: a tenth of the campus still open
  {
    const core::TeamConfig team = campus_team(16);
    const auto map = make_map(team, team_open_share);
    const PlannerOptions options = PlannerOptions::from(team.params);
    std::printf("campus map: %zu supervoxels, %zu graph vertices, %zu edges; %.0f %% open; hexplore planner, GA %d x %d "
                "generations in %.0f ms; %d rounds per row (thread CPU time, ms)\n\n",
                map->size(), map->graph().vertex_count(), map->graph().edge_count(), 100 * team_open_share,
                options.ga_population, options.ga_max_generations, 1e3 * options.ga_time_budget_s, rounds);
  }
  std::ofstream team_csv, work_csv;
  if (!csv_dir.empty()) {
    team_csv.open(csv_dir + "/planning_scale_team.csv");
    work_csv.open(csv_dir + "/planning_scale_work.csv");
    if (!team_csv || !work_csv) {
      std::fprintf(stderr, "cannot write CSV files into '%s'\n", csv_dir.c_str());
      return 1;
    }
    team_csv << "robots,views,clusters,views_ms,clustering_ms,assignment_ms,mnss_ms,total_mean_ms,total_p95_ms,"
                "generations_mean,graph_searches_mean,agreement,agreement_with_reference\n";
    work_csv << "open_share,views,clusters,views_ms,clustering_ms,assignment_ms,mnss_ms,total_mean_ms,total_p95_ms,"
                "generations_mean,graph_searches_mean\n";
  }

  std::printf("1. team size (%.0f %% open)\n", 100 * team_open_share);
  std::printf("%6s %6s %8s | %8s %8s %8s %8s | %8s %8s | %6s %8s | %9s %9s\n", "robots", "views", "clusters", "views",
              "cluster", "assign", "mnss", "mean", "p95", "gens", "searches", "agree", "agree+ref");
  for (const int n : {2, 4, 8, 16}) {
    const core::TeamConfig team = campus_team(n);
    const Rounds r = run_rounds(registry, team, team_open_share, rounds);
    const auto [agree, agree_ref] = agreement(registry, team, team_open_share);
    std::printf("%6d %6d %8d | %8.1f %8.1f %8.1f %8.1f | %8.1f %8.1f | %6.0f %8.0f | %9.2f %9.2f\n", n, r.view_count,
                r.clusters, mean(r.views), mean(r.clustering), mean(r.assignment), mean(r.mnss), mean(r.total),
                p95(r.total), mean(r.generations), mean(r.searches), agree, agree_ref);
    if (team_csv)
      team_csv << n << ',' << r.view_count << ',' << r.clusters << ',' << mean(r.views) << ',' << mean(r.clustering)
               << ',' << mean(r.assignment) << ',' << mean(r.mnss) << ',' << mean(r.total) << ',' << p95(r.total) << ','
               << mean(r.generations) << ',' << mean(r.searches) << ',' << agree << ',' << agree_ref << '\n';
  }

  std::printf("\n2. work (16 robots): round time against clusters and views\n");
  std::printf("%6s %6s %8s | %8s %8s %8s %8s | %8s %8s | %6s %8s\n", "open", "views", "clusters", "views", "cluster",
              "assign", "mnss", "mean", "p95", "gens", "searches");
  const core::TeamConfig team = campus_team(16);
  std::vector<std::pair<double, double>> clusters_vs_ms;
  for (const double open : {0.02, 0.04, 0.07, 0.1, 0.15, 0.2, 0.3}) {
    const Rounds r = run_rounds(registry, team, open, rounds);
    std::printf("%5.0f%% %6d %8d | %8.1f %8.1f %8.1f %8.1f | %8.1f %8.1f | %6.0f %8.0f\n", 100 * open, r.view_count,
                r.clusters, mean(r.views), mean(r.clustering), mean(r.assignment), mean(r.mnss), mean(r.total),
                p95(r.total), mean(r.generations), mean(r.searches));
    if (r.clusters > 0) clusters_vs_ms.push_back({double(r.clusters), mean(r.total)});
    if (work_csv)
      work_csv << open << ',' << r.view_count << ',' << r.clusters << ',' << mean(r.views) << ',' << mean(r.clustering)
               << ',' << mean(r.assignment) << ',' << mean(r.mnss) << ',' << mean(r.total) << ',' << p95(r.total) << ','
               << mean(r.generations) << ',' << mean(r.searches) << '\n';
  }
  if (clusters_vs_ms.size() >= 2) {
    const auto& a = clusters_vs_ms.front();
    const auto& b = clusters_vs_ms.back();
    std::printf("round time grows as clusters^%.2f between %.0f and %.0f clusters\n",
                std::log(b.second / a.second) / std::log(b.first / a.first), a.first, b.first);
  }
  return 0;
}
