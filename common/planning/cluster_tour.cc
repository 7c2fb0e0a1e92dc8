#include "common/planning/cluster_tour.h"

#include <unordered_map>

#include "common/planning/graph_tour.h"
#include "common/planning/labels.h"
#include "common/planning/mnss.h"

namespace hexplore::planning {

std::vector<RobotPlan> cluster_plans(const AssignmentInstance& inst, const std::vector<TaskCluster>& clusters,
                                     const std::vector<RobotState>& robots, const std::vector<Route>& routes) {
  std::vector<RobotPlan> plans(robots.size());
  for (size_t r = 0; r < robots.size(); ++r) {
    RobotPlan& plan = plans[r];
    plan.robot_id = robots[r].id;
    const int k = robots[r].species;
    int prev = inst.problem.depot(int(r));
    for (int c : routes[r]) {
      const TaskCluster& cl = clusters[size_t(inst.city_cluster[size_t(c)])];
      plan.cluster_ids.push_back(cl.id);
      plan.cluster_centers.push_back(cl.center);
      const double travel_s = inst.problem.travel_cost(k, prev, c);
      const double cost_s = travel_s + inst.problem.execution_cost(k, c);
      plan.route_length_m += travel_s * inst.speed[size_t(k)];
      plan.cost_s += cost_s;
      if (cl.label != kPublic) plan.private_cost_s += cost_s;
      prev = c;
    }
  }
  return plans;
}

std::optional<double> reference_agreement(const ReferenceSolution& reference, const std::vector<RobotPlan>& plans) {
  std::unordered_map<uint64_t, std::string> owner;
  for (const auto& route : reference.routes)
    for (uint64_t id : route.cluster_ids) owner[id] = route.robot_id;
  int agree = 0, compared = 0;
  for (const RobotPlan& plan : plans)
    for (uint64_t id : plan.cluster_ids)
      if (const auto it = owner.find(id); it != owner.end()) {
        ++compared;
        agree += it->second == plan.robot_id ? 1 : 0;
      }
  if (compared == 0) return std::nullopt;
  return double(agree) / compared;
}

std::vector<TaskView> every_view(const std::vector<TaskView>& views, const TaskCluster& cluster,
                                 const Eigen::Vector3d& start, const std::optional<Eigen::Vector3d>& end) {
  std::vector<TaskView> all;
  for (int v : cluster.views) all.push_back(views[size_t(v)]);
  return order_views(std::move(all), start, end);
}

std::vector<TaskView> cluster_tour(const highlevel::TopologyGraph& graph, const AssignmentInstance& inst,
                                   const std::vector<TaskCluster>& clusters, const Route& route,
                                   const RobotState& self, int graph_species, std::optional<uint64_t> at_vertex,
                                   const ClusterViews& views_of) {
  const auto cluster_at = [&](size_t i) -> const TaskCluster& {
    return clusters[size_t(inst.city_cluster[size_t(route[i])])];
  };
  std::vector<TaskView> tour;
  for (size_t i = 0; i < route.size(); ++i) {
    const Eigen::Vector3d start = i == 0 ? self.position : cluster_at(i - 1).center;
    std::optional<Eigen::Vector3d> end;
    if (i + 1 < route.size()) end = cluster_at(i + 1).center;
    std::vector<TaskView> part = views_of(cluster_at(i), start, end);
    if (at_vertex && part.size() > 1) {
      std::optional<uint64_t> next_anchor;
      if (i + 1 < route.size())
        if (const uint64_t a = inst.anchor[size_t(inst.city_cluster[size_t(route[i + 1])])][size_t(self.species)])
          next_anchor = a;
      part = order_views_on_graph(graph, *at_vertex, part, graph_species, next_anchor);
    }
    if (!part.empty()) at_vertex = part.back().ground_key;
    tour.insert(tour.end(), part.begin(), part.end());
  }
  return tour;
}

}  // namespace hexplore::planning
