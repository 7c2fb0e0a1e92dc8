#pragma once
// MROMT+ (BASELINES.md; after Dong et al., "Multi-Robot Collaborative Dense Scene
// Reconstruction", SIGGRAPH 2019, and its public CoScan code): candidate views (task views
// plus MNSS-style ones nearby) scored by the uncertain targets they see go through a lazy
// greedy priority queue with co-visibility pruning, at most 8 per robot per round (the
// nearest to the team); a capability-aware Lloyd clustering and a Hungarian robot-cluster
// matching on travel time give each robot one compact cluster (extra clusters wait for a
// later round); each robot orders its cluster by an open TSP on graph distance.
// Deterministic on identical input and shares no route.

#include <string>

#include "common/planning/planner_base.h"

namespace hexplore::planning {

// CoScan's batch: views accepted per robot per round.
inline constexpr int kMromtViewsPerRobot = 8;

class MromtPlanner : public ConfiguredPlanner {
 public:
  std::string name() const override { return "mromt+"; }
  PlanResult plan(const PlanRequest& request) override;
  RouteSharing route_sharing() const override { return RouteSharing::kNone; }
};

}  // namespace hexplore::planning
