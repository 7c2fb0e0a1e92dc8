#pragma once
// What the cluster planners (hexplore and its ablations, TSPGA+) make of an assignment: each
// robot's team-solution entry (cluster sequence, route length, cost) and the planning robot's
// exploration tour through its clusters. Both planners visit a cluster's chosen views in graph
// order (paper eq. 4-xx-delta: a cluster costs graph distances), from where the previous
// cluster's views end towards the next cluster's anchor; Euclidean order crosses a building's
// walls back and forth (README, "Views in graph order"). Which views of a cluster are visited
// is the planner's choice (MNSS, every view, one view).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/topology_graph.h"
#include "common/planning/clustering.h"
#include "common/planning/cost_model.h"
#include "common/planning/planning_types.h"
#include "common/planning/reference.h"

namespace hexplore::planning {

// Every robot's plan for `routes` (per robot, cities of `inst`): cluster ids and centres in
// route order, graph route length, cost (travel + execution) and the part of it spent on
// clusters private to the robot's species. Routes (views) stay empty.
std::vector<RobotPlan> cluster_plans(const AssignmentInstance& inst, const std::vector<TaskCluster>& clusters,
                                     const std::vector<RobotState>& robots, const std::vector<Route>& routes);

// Share of the plans' clusters that the reference assigns to the same robot, over the clusters
// the reference assigns at all; nullopt when it assigns none of them.
std::optional<double> reference_agreement(const ReferenceSolution& reference, const std::vector<RobotPlan>& plans);

// The views a planner visits in one cluster, between `start` (the robot, or the previous
// cluster's centre) and `end` (the next cluster's centre, if any).
using ClusterViews = std::function<std::vector<TaskView>(const TaskCluster& cluster, const Eigen::Vector3d& start,
                                                         const std::optional<Eigen::Vector3d>& end)>;

// Every view of the cluster in Euclidean order from start towards end (the no-mnss tour).
std::vector<TaskView> every_view(const std::vector<TaskView>& views, const TaskCluster& cluster,
                                 const Eigen::Vector3d& start, const std::optional<Eigen::Vector3d>& end);

// The tour of robot `self` through its route's clusters: each cluster's `views_of`, put in
// graph order for `graph_species` from the robot's vertex (`at_vertex`; without one the
// views keep views_of's order).
std::vector<TaskView> cluster_tour(const highlevel::TopologyGraph& graph, const AssignmentInstance& inst,
                                   const std::vector<TaskCluster>& clusters, const Route& route,
                                   const RobotState& self, int graph_species, std::optional<uint64_t> at_vertex,
                                   const ClusterViews& views_of);

}  // namespace hexplore::planning
