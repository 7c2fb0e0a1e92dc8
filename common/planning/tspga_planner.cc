#include "common/planning/tspga_planner.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "common/planning/clustering.h"
#include "common/planning/cost_model.h"
#include "common/planning/mnss.h"
#include "common/planning/round_inputs.h"
#include "common/planning/utility_greedy.h"

namespace hexplore::planning {

PlanResult TspgaPlanner::plan(const PlanRequest& req) {
  const PlannerContext& context = checked(req);
  const TeamCapabilities& team = context.team;
  const PlannerOptions& o = context.options;
  StageClock clock(o);

  const highlevel::TopologyGraph& graph = req.map->graph();
  const RoundInputs in = prepare_round(req, team, o);
  const std::vector<TaskView>& views = in.views;
  PlanResult out = start_result(req, in);
  out.times.views_s = clock.lap();

  const std::vector<TaskCluster> clusters = cluster_views(views, o.eta_r_m);
  out.clusters = int(clusters.size());
  out.times.clustering_s = clock.lap();

  // The hexplore cost model over the clusters (labels: public, or private to one species).
  const AssignmentInstance inst = build_assignment(graph, views, clusters, team, req.robots, in.robot_vertices);
  out.dropped_clusters = int(inst.dropped.size());
  for (int c : inst.city_cluster) out.open_views += int(clusters[size_t(c)].views.size());
  std::vector<double> gain;
  for (int c : inst.city_cluster) {
    std::unordered_set<uint64_t> targets;
    for (int v : clusters[size_t(c)].views) targets.insert(views[size_t(v)].targets.begin(), views[size_t(v)].targets.end());
    gain.push_back(double(targets.size()));
  }
  const double lambda = std::log(2.0) / kTspgaHalfLifeS;
  std::vector<Route> routes(req.robots.size());
  if (inst.problem.num_cities > 0) routes = greedy_allocation(inst.problem, gain, lambda);
  out.times.assignment_s = clock.lap();

  out.robots.resize(req.robots.size());
  for (size_t r = 0; r < req.robots.size(); ++r) {
    RobotPlan& plan = out.robots[r];
    plan.robot_id = req.robots[r].id;
    const int k = req.robots[r].species;
    int prev = inst.problem.depot(int(r));
    for (int c : routes[r]) {
      const TaskCluster& cl = clusters[size_t(inst.city_cluster[size_t(c)])];
      plan.cluster_ids.push_back(cl.id);
      plan.cluster_centers.push_back(cl.center);
      const double w = inst.problem.travel_cost(k, prev, c);
      plan.route_length_m += w * inst.speed[size_t(k)];
      plan.cost_s += w + inst.problem.execution_cost(k, c);
      prev = c;
    }
    out.fitness += route_utility(inst.problem, int(r), routes[r], gain, lambda);
  }

  // The planning robot visits every view of its clusters in order, between the previous and
  // the next cluster centre (the no-mnss tour).
  const size_t self = size_t(req.self);
  const Route& mine = routes[self];
  for (size_t i = 0; i < mine.size(); ++i) {
    const TaskCluster& cl = clusters[size_t(inst.city_cluster[size_t(mine[i])])];
    const Eigen::Vector3d start =
        i == 0 ? req.robots[self].position : clusters[size_t(inst.city_cluster[size_t(mine[i - 1])])].center;
    std::optional<Eigen::Vector3d> end;
    if (i + 1 < mine.size()) end = clusters[size_t(inst.city_cluster[size_t(mine[i + 1])])].center;
    std::vector<TaskView> all;
    for (int v : cl.views) all.push_back(views[size_t(v)]);
    const std::vector<TaskView> part = order_views(std::move(all), start, end);
    out.robots[self].route.insert(out.robots[self].route.end(), part.begin(), part.end());
  }
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

}  // namespace hexplore::planning
