#include "common/planning/tspga_planner.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "common/planning/cluster_tour.h"
#include "common/planning/clustering.h"
#include "common/planning/cost_model.h"
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

  // The hexplore cost model over the clusters (labels: public, or private to one species);
  // its tours visit every view of a cluster, so delta charges every view.
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

  out.robots = cluster_plans(inst, clusters, req.robots, routes);
  for (size_t r = 0; r < req.robots.size(); ++r)
    out.fitness += route_utility(inst.problem, int(r), routes[r], gain, lambda);

  // The planning robot visits every view of its clusters (the no-mnss tour: Euclidean order
  // between the previous and the next cluster centre, then graph order, as hexplore's).
  const size_t self = size_t(req.self);
  const RobotState& me = req.robots[self];
  const ClusterViews every = [&](const TaskCluster& cl, const Eigen::Vector3d& start,
                                 const std::optional<Eigen::Vector3d>& end) { return every_view(views, cl, start, end); };
  out.robots[self].route = cluster_tour(graph, inst, clusters, routes[self], me, team.graph_species_of(me.species),
                                        in.robot_vertices[self], every);
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

}  // namespace hexplore::planning
