#include "common/planning/hexplore_planner.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "common/core/clock.h"
#include "common/planning/cluster_tour.h"
#include "common/planning/clustering.h"
#include "common/planning/cost_model.h"
#include "common/planning/graph_tour.h"
#include "common/planning/labels.h"
#include "common/planning/mnss.h"
#include "common/planning/mtsp/ga_solver.h"
#include "common/core/rng.h"
#include "common/planning/round_inputs.h"
#include "common/planning/route_pruning.h"

namespace hexplore::planning {
namespace {

// A seed every robot derives alike from shared state (the option seed and the cluster ids),
// so identical maps give identical GA runs whatever each robot's local round counter says.
uint64_t shared_seed(uint64_t base, const std::vector<uint64_t>& ids) {
  uint64_t s = core::mix_seed(base, ids.size());
  for (uint64_t id : ids) s = core::mix_seed(s, id);
  return s;
}

// The reference assignment mapped onto this round's clusters: each robot keeps its reference
// clusters that still exist (in reference order); the rest go, in id order, to the eligible
// robot whose route grows least. Gives the GA a starting point that agrees with the team.
std::vector<Route> reference_seed(const MtspProblem& p, const std::vector<uint64_t>& city_ids,
                                  const ReferenceSolution& ref, const std::vector<RobotState>& robots) {
  std::unordered_map<uint64_t, int> city_of;
  for (size_t c = 0; c < city_ids.size(); ++c) city_of[city_ids[c]] = int(c);
  std::vector<Route> routes(robots.size());
  std::vector<char> placed(city_ids.size(), 0);
  for (size_t r = 0; r < robots.size(); ++r) {
    const ReferenceRoute* rr = ref.route_of(robots[r].id);
    if (!rr) continue;
    for (uint64_t id : rr->cluster_ids) {
      const auto it = city_of.find(id);
      if (it == city_of.end() || placed[size_t(it->second)] || !p.eligible(int(r), it->second)) continue;
      routes[r].push_back(it->second);
      placed[size_t(it->second)] = 1;
    }
  }
  for (size_t c = 0; c < city_ids.size(); ++c) {
    if (placed[c]) continue;
    int best = -1;
    double best_cost = kInfinity;
    for (size_t r = 0; r < robots.size(); ++r) {
      if (!p.eligible(int(r), int(c))) continue;
      const int s = p.robots[r].species;
      const int last = routes[r].empty() ? p.depot(int(r)) : routes[r].back();
      const double add = p.travel_cost(s, last, int(c)) + p.execution_cost(s, int(c));
      if (add < best_cost) best_cost = add, best = int(r);
    }
    if (best >= 0) routes[size_t(best)].push_back(int(c));
  }
  return routes;
}

}  // namespace

ReferenceSolution PlanResult::as_reference(const std::string& source_robot) const {
  ReferenceSolution s;
  s.source_robot = source_robot;
  s.round = round;
  for (const auto& r : robots) s.routes.push_back({r.robot_id, r.cluster_ids, r.cluster_centers, r.route_length_m});
  return s;
}

std::string HexplorePlanner::name() const {
  switch (ablation_) {
    case Ablation::kNone: return "hexplore";
    case Ablation::kNoHetero: return "no-hetero";
    case Ablation::kNoCluster: return "no-cluster";
    case Ablation::kNoMnss: return "no-mnss";
    case Ablation::kNoAssign: return "no-assign";
  }
  return "hexplore";
}

PlanResult HexplorePlanner::plan(const PlanRequest& req) {
  const PlannerContext& context = checked(req);
  const TeamCapabilities team = ablation_ == Ablation::kNoHetero ? context.team.homogeneous() : context.team;
  if (ablation_ == Ablation::kNoAssign) return plan_voronoi(req, team, context.options);

  const PlannerOptions& o = context.options;
  StageClock clock(o);

  // Task views, standing only where some robot can drive to.
  const highlevel::TopologyGraph& graph = req.map->graph();
  const RoundInputs in = prepare_round(req, team, o);
  const std::vector<TaskView>& views = in.views;
  PlanResult out = start_result(req, in);
  out.path_species = team.graph_species_of(req.robots[size_t(req.self)].species);
  out.times.views_s = clock.lap();

  // Clustering.
  const std::vector<TaskCluster> clusters =
      ablation_ == Ablation::kNoCluster ? singleton_clusters(views) : cluster_views(views, o.eta_r_m);
  out.clusters = int(clusters.size());
  out.times.clustering_s = clock.lap();

  // Assignment.
  // delta charges what the tours will stand at: MNSS's cover, or every view without MNSS.
  const CoverReading cover{*in.context, o};
  const bool charge_cover = o.cover_cluster_work && ablation_ != Ablation::kNoMnss && ablation_ != Ablation::kNoCluster;
  const AssignmentInstance inst =
      build_assignment(graph, views, clusters, team, req.robots, in.robot_vertices, charge_cover ? &cover : nullptr);
  out.dropped_clusters = int(inst.dropped.size());
  for (int c : inst.city_cluster) out.open_views += int(clusters[size_t(c)].views.size());
  std::vector<uint64_t> city_ids;
  for (int c : inst.city_cluster) city_ids.push_back(clusters[size_t(c)].id);

  std::optional<ReferenceSolution> ref;
  if (auto i = select_reference(req.shared)) ref = req.shared[*i];
  if (ref) out.reference_source = ref->source_robot;
  std::vector<std::vector<Eigen::Vector3d>> ref_lines(req.robots.size());
  if (ref)
    for (size_t r = 0; r < req.robots.size(); ++r)
      if (const ReferenceRoute* rr = ref->route_of(req.robots[r].id)) ref_lines[r] = rr->centers;

  std::vector<Route> routes(req.robots.size());
  if (inst.problem.num_cities > 0) {
    const FitnessModel model(inst.problem, FitnessWeights{o.beta_c, o.beta_m, o.beta_d, o.beta_e, o.reference_window}, ref_lines);
    GaOptions ga;
    ga.population = o.ga_population;
    ga.max_generations = o.ga_max_generations;
    ga.time_budget_s = o.ga_time_budget_s;
    ga.seed = shared_seed(o.seed, city_ids);
    ga.local_search = o.ga_memetic ? LocalSearchMode::kMemetic : LocalSearchMode::kNone;
    ga.budget_clock = o.cpu_clock ? BudgetClock::kThreadCpu : BudgetClock::kWall;
    if (ref) ga.seeds.push_back(reference_seed(inst.problem, city_ids, *ref, req.robots));
    const GaResult result = solve_ga(model, ga);
    routes = result.routes;
    out.fitness = result.breakdown.fitness;
    out.ga_generations = result.generations;
  }
  out.times.assignment_s = clock.lap();

  // Team solution: cluster sequences, lengths and costs, and how far it agrees with the reference.
  out.robots = cluster_plans(inst, clusters, req.robots, routes);
  if (ref) out.agreement = reference_agreement(*ref, out.robots);

  // Exploration tour of the planning robot: MNSS's views of each cluster (every view without
  // MNSS, the first without clustering), in graph order.
  const size_t self = size_t(req.self);
  const RobotState& me = req.robots[self];
  const SpeciesCapability& my_species = team.species[size_t(me.species)];
  core::PlanRng rng(shared_seed(core::mix_seed(o.seed, 0x4d4e5353), city_ids));
  const ClusterViews views_of = [&](const TaskCluster& cl, const Eigen::Vector3d& start,
                                    const std::optional<Eigen::Vector3d>& end) -> std::vector<TaskView> {
    if (ablation_ == Ablation::kNoCluster) return {views[size_t(cl.views.front())]};
    if (ablation_ == Ablation::kNoMnss) return every_view(views, cl, start, end);
    // MNSS picks the set with Euclidean costs (too many candidates for a Dijkstra each).
    return mnss_tour(*in.context, views, cl.views, {cl.center}, o.eta_r_m, my_species, start, end, o, rng, nullptr,
                     &in.reachable[size_t(me.species)]);
  };
  std::vector<TaskView>& tour = out.robots[self].route;
  tour = cluster_tour(graph, inst, clusters, routes[self], me, team.graph_species_of(me.species),
                      in.robot_vertices[self], views_of);
  if (ablation_ != Ablation::kNoMnss) tour = prune_route(*in.context, std::move(tour), my_species, o);
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

PlanResult HexplorePlanner::plan_voronoi(const PlanRequest& req, const TeamCapabilities& team,
                                         const PlannerOptions& o) const {
  StageClock clock(o);
  const highlevel::TopologyGraph& graph = req.map->graph();
  const RoundInputs in = prepare_round(req, team, o);
  const MapContext& ctx = *in.context;
  const auto& reach = in.reachable;
  const std::vector<TaskView>& views = in.views;
  PlanResult out = start_result(req, in);
  out.path_species = team.graph_species_of(req.robots[size_t(req.self)].species);
  out.times.views_s = clock.lap();

  // Dynamic Voronoi partition: each view goes to the nearest (graph distance) robot whose
  // species may take it; ties to the lower robot index.
  const size_t R = req.robots.size();
  const std::vector<std::optional<uint64_t>>& vertex = in.robot_vertices;
  std::vector<std::vector<int>> owned(R);
  for (size_t v = 0; v < views.size(); ++v) {
    int best = -1;
    double bd = kInfinity;
    for (size_t r = 0; r < R; ++r) {
      const int k = req.robots[r].species;
      if (!vertex[r] || (views[v].label != kPublic && views[v].label != k)) continue;
      const double d = graph.dist(*vertex[r], views[v].ground_key, team.graph_species_of(k));
      if (d < bd) bd = d, best = int(r);
    }
    if (best >= 0) owned[size_t(best)].push_back(int(v));
    else ++out.dropped_clusters;
  }
  out.times.assignment_s = clock.lap();

  out.robots.resize(R);
  core::PlanRng rng(core::mix_seed(o.seed, views.size()));
  for (size_t r = 0; r < R; ++r) {
    RobotPlan& plan = out.robots[r];
    plan.robot_id = req.robots[r].id;
    std::vector<TaskView> mine;
    for (int v : owned[r]) mine.push_back(views[size_t(v)]);
    mine = order_views(std::move(mine), req.robots[r].position, std::nullopt);
    for (const auto& v : mine) {
      plan.cluster_ids.push_back(v.key);
      plan.cluster_centers.push_back(v.position);
    }
    plan.route_length_m = tour_length(mine, req.robots[r].position, std::nullopt);
    plan.cost_s = plan.route_length_m / std::max(1e-6, team.species[size_t(req.robots[r].species)].speed_mps);
    if (int(r) == req.self && !owned[r].empty()) {
      std::vector<Eigen::Vector3d> around;
      for (int v : owned[r]) around.push_back(views[size_t(v)].position);
      const SpeciesCapability& species = team.species[size_t(req.robots[r].species)];
      std::vector<TaskView> tour = mnss_tour(ctx, views, owned[r], around, 0.5 * o.eta_r_m, species,
                                             req.robots[r].position, std::nullopt, o, rng, nullptr,
                                             &reach[size_t(req.robots[r].species)]);
      // In graph order, like the full planner's clusters (plan()).
      if (vertex[r]) tour = order_views_on_graph(graph, *vertex[r], tour, team.graph_species_of(req.robots[r].species));
      plan.route = prune_route(ctx, std::move(tour), species, o);
    }
  }
  out.clusters = int(views.size()) - out.dropped_clusters;
  out.open_views = out.clusters;
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

}  // namespace hexplore::planning
