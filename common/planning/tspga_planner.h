#pragma once
// TSPGA+ (BASELINES.md; after Hardouin et al., "A Multirobot System for 3-D Surface
// Reconstruction With Centralized and Distributed Architectures", T-RO 2023): hexplore's
// greedy sequential clustering (so every robot sees the same clusters), a cluster's gain =
// the distinct ISE supervoxels its views cover, greedy allocation of clusters to robots by
// the largest utility increase (utility_greedy.h), 2-opt of each robot's cluster order, and
// inside a cluster every view visited (the no-mnss tour, no view merging). Deterministic
// on identical input and shares no route.

#include <string>

#include "common/planning/planner_base.h"

namespace hexplore::planning {

// The utility's discount: a cluster's gain halves for every this many seconds until the
// robot has finished it (about the time to cross the paper's multi-building site, 45 m at
// SLUGCAT's 0.4 m/s). Chosen once, not tuned (common/planning/README.md "Baselines").
inline constexpr double kTspgaHalfLifeS = 120.0;

class TspgaPlanner : public ConfiguredPlanner {
 public:
  std::string name() const override { return "tspga+"; }
  PlanResult plan(const PlanRequest& request) override;
  RouteSharing route_sharing() const override { return RouteSharing::kNone; }
};

}  // namespace hexplore::planning
