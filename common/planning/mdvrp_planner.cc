#include "common/planning/mdvrp_planner.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

#include "common/core/rng.h"
#include "common/planning/round_inputs.h"
#include "common/planning/view_costs.h"
#include "common/planning/vrp_instance.h"
#include "common/planning/vrp_search.h"

namespace hexplore::planning {
namespace {

// FNV-1a: a robot id as a seed salt that is the same on every platform (std::hash is not).
uint64_t stable_hash(const std::string& s) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

// One shared solution projected onto today's nodes: each robot keeps, in order, the views of
// its shared route that still exist and that it may still serve; views that are new (or that
// it may no longer serve) are cheapest-inserted afterwards, in key order.
VrpRoutes project(const VrpInstance& inst, const ReferenceSolution& shared, const std::vector<RobotState>& robots,
                  const std::unordered_map<uint64_t, int>& node_of_key, const std::vector<int>& order) {
  VrpRoutes routes(robots.size());
  std::vector<char> placed(size_t(inst.customers), 0);
  for (size_t r = 0; r < robots.size(); ++r) {
    const ReferenceRoute* route = shared.route_of(robots[r].id);
    if (!route) continue;
    for (uint64_t key : route->cluster_ids) {
      const auto it = node_of_key.find(key);
      if (it == node_of_key.end() || placed[size_t(it->second)] || !inst.eligible(int(r), it->second)) continue;
      routes[r].push_back(it->second);
      placed[size_t(it->second)] = 1;
    }
  }
  return cheapest_insertion(inst, std::move(routes), order);
}

}  // namespace

PlanResult MdvrpPlanner::plan(const PlanRequest& req) {
  const PlannerContext& context = checked(req);
  const TeamCapabilities& team = context.team;
  const PlannerOptions& o = context.options;
  StageClock clock(o);

  const highlevel::TopologyGraph& graph = req.map->graph();
  const RoundInputs in = prepare_round(req, team, o);
  const std::vector<TaskView>& views = in.views;
  PlanResult out = start_result(req, in);
  out.clusters = int(views.size());  // every view is its own node
  out.times.views_s = clock.lap();

  // The per-robot cost matrices of the vehicle-routing problem.
  ViewCosts costs = build_view_costs(graph, views, team, req.robots, in.robot_vertices, in.reachable);
  const int N = costs.nodes();
  const size_t R = req.robots.size();
  out.dropped_clusters = int(costs.unservable.size());
  out.open_views = N;
  VrpInstance inst;
  inst.customers = N;
  inst.vehicle_class = costs.robot_species;
  inst.travel = std::move(costs.travel);
  inst.service = std::move(costs.service);
  std::unordered_map<uint64_t, int> node_of_key;
  std::vector<int> key_order(static_cast<size_t>(N));
  for (int n = 0; n < N; ++n) {
    node_of_key[views[size_t(costs.view_of_node[size_t(n)])].key] = n;
    key_order[size_t(n)] = n;  // nodes follow the views' key order
  }

  // Warm start (the source's min-max rule): every shared solution, the own previous one
  // included, projected onto today's views; the lexicographic best by (dropped, longest
  // route), then objective, then source id. Without any, a cheapest-insertion start.
  std::vector<const ReferenceSolution*> shared;
  for (const auto& s : req.shared) shared.push_back(&s);
  std::sort(shared.begin(), shared.end(),
            [](const ReferenceSolution* a, const ReferenceSolution* b) { return a->source_robot < b->source_robot; });
  VrpRoutes start;
  const ReferenceSolution* reference = nullptr;
  std::tuple<int, double, double> best_key{0, 0.0, 0.0};
  for (const ReferenceSolution* s : shared) {
    VrpRoutes candidate = project(inst, *s, req.robots, node_of_key, key_order);
    const VrpCost c = vrp_cost(inst, candidate);
    const auto key = std::make_tuple(c.dropped, c.longest, c.objective);
    if (!reference || key < best_key) {
      reference = s;
      best_key = key;
      start = std::move(candidate);
    }
  }
  if (!reference) start = cheapest_insertion(inst, VrpRoutes(R), key_order);

  // Guided local search under the GA's budget: its generations (lockstep) and wall time
  // (processes). The move order is seeded per robot and round, so robots diverge as
  // time-limited solvers do; the warm start pulls them back together.
  GlsOptions gls;
  gls.max_evaluations = int64_t(std::max(0, o.ga_max_generations)) * kMdvrpEvaluationsPerGeneration;
  gls.time_budget_s = o.ga_time_budget_s;
  gls.clock = o.cpu_clock ? BudgetClock::kThreadCpu : BudgetClock::kWall;
  gls.seed = core::mix_seed(core::mix_seed(o.seed, stable_hash(req.robots[size_t(req.self)].id)), req.round);
  VrpRoutes routes = start;
  if (N > 0) {
    const GlsResult result = guided_local_search(inst, start, gls);
    routes = result.routes;
    out.fitness = result.cost.objective;
  }
  out.times.assignment_s = clock.lap();

  // Team solution: view keys in visiting order; agreement with the warm-start source.
  std::unordered_map<uint64_t, std::string> ref_owner;
  if (reference)
    for (const auto& rr : reference->routes)
      for (uint64_t id : rr.cluster_ids) ref_owner[id] = rr.robot_id;
  int agree = 0, compared = 0;
  out.robots.resize(R);
  for (size_t r = 0; r < R; ++r) {
    RobotPlan& plan = out.robots[r];
    plan.robot_id = req.robots[r].id;
    const int k = req.robots[r].species;
    int prev = inst.depot(int(r));
    for (int n : routes[r]) {
      const TaskView& view = views[size_t(costs.view_of_node[size_t(n)])];
      plan.cluster_ids.push_back(view.key);
      plan.cluster_centers.push_back(view.position);
      plan.route_length_m += inst.travel[size_t(k)](prev, n) * costs.speed[size_t(k)];
      prev = n;
      if (const auto it = ref_owner.find(view.key); it != ref_owner.end()) {
        ++compared;
        agree += it->second == plan.robot_id ? 1 : 0;
      }
    }
    plan.cost_s = vrp_route_cost(inst, int(r), routes[r]);
    if (int(r) == req.self)
      for (int n : routes[r]) plan.route.push_back(views[size_t(costs.view_of_node[size_t(n)])]);
  }
  if (compared > 0) out.agreement = double(agree) / compared;
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

}  // namespace hexplore::planning
