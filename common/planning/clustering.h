#pragma once
// Task-view clustering (paper "Task-View Clustering"): greedy sequential clustering per label
// over the views ordered by supervoxel hash key, so every robot with the same views forms the
// same clusters whatever order it received the map in.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "common/planning/task_views.h"

namespace hexplore::planning {

struct TaskCluster {
  uint64_t id = 0;               // key of its first view in key order (plan.proto ClusterSequence)
  int label = -1;                // kPublic or species index (f_c)
  std::vector<int> views;        // indices into the view list, ascending key
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // p(tau): mean view position
  int facade_views = 0;          // |Xi_u^tau|
};

// Clusters of radius eta_r: a cluster starts at the first remaining view in key order and
// repeatedly takes, in key order, every remaining view of the same label within eta_r of its
// current centre (the mean of its members) until a full scan adds none. Clusters are returned
// ordered by id. The input order of `views` does not matter.
std::vector<TaskCluster> cluster_views(const std::vector<TaskView>& views, double eta_r_m);

// One cluster per view (ablation NoCluster).
std::vector<TaskCluster> singleton_clusters(const std::vector<TaskView>& views);

}  // namespace hexplore::planning
