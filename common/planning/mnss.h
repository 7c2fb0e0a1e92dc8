#pragma once
// Exploration-tour generation (paper "Exploration Tour Generation", minimal view-set sampling
// after MNSS): inside one assigned cluster, candidate views on nearby ground the species may
// stand on, a score matrix against the cluster's ISE supervoxels, score-proportional sampling
// of view sets that cover them, and the cheapest order between a virtual start (previous
// cluster centre) and a virtual end (next cluster centre).

#include <optional>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/planning/capabilities.h"
#include "common/planning/clustering.h"
#include "common/core/rng.h"
#include "common/planning/task_views.h"

namespace hexplore::planning {

struct TourStats {
  int candidates = 0;
  int targets = 0;
  int uncoverable = 0;  // targets no candidate sees; their original task view is kept
  int64_t rays = 0;
};

// Cheapest visiting order of `views` (Euclidean, speed-independent) from `start` to the
// optional `end`: nearest neighbour, then 2-opt with both ends fixed.
std::vector<TaskView> order_views(std::vector<TaskView> views, const Eigen::Vector3d& start,
                                  const std::optional<Eigen::Vector3d>& end);
// Length of start -> views -> end.
double tour_length(const std::vector<TaskView>& views, const Eigen::Vector3d& start,
                   const std::optional<Eigen::Vector3d>& end);

// The MNSS view sequence of a set of task views (a cluster's) for a robot of `species`.
// Candidates stand on ground within `radius` of any point of `neighbourhood` (a cluster:
// its centre and eta_r). `reachable` (optional) holds the ground keys the robot can drive
// to; candidates elsewhere are skipped.
std::vector<TaskView> mnss_tour(const MapContext& ctx, const std::vector<TaskView>& views,
                                const std::vector<int>& view_indices, const std::vector<Eigen::Vector3d>& neighbourhood,
                                double radius, const SpeciesCapability& species, const Eigen::Vector3d& start,
                                const std::optional<Eigen::Vector3d>& end, const PlannerOptions& o, core::PlanRng& rng,
                                TourStats* stats = nullptr,
                                const std::unordered_set<uint64_t>* reachable = nullptr);

}  // namespace hexplore::planning
