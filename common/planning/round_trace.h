#pragma once
// One line of the planning service's per-round trace (--trace-dir): what the round saw, what
// it decided and how the route follower fared so far, as one JSON object per line
// (common/planning/README.md, "Why views remain").

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/planning/planner.h"
#include "common/planning/route_follower.h"

namespace hexplore::highlevel {
class HighLevelMap;
}

namespace hexplore::planning {

struct RoundTrace {
  double t_s = 0.0;
  uint64_t round = 0;
  std::string reason;
  std::string planner;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double odometry_m = 0.0;
  size_t given_up = 0;              // targets the team gave up on
  uint64_t passing_observations = 0;
  std::vector<Eigen::Vector3d> follower_next;  // the follower's next views after it merged the round's route
  std::vector<TargetJudgement> judged;         // targets the follower judged since the last round
};

// The JSON line (with its newline) for one round of `req` / `res` on `map`; supervoxels are
// counted inside `region` only.
std::string round_trace_json(const RoundTrace& round, const PlanRequest& req, const PlanResult& res,
                             const FollowerCounters& follower, const highlevel::HighLevelMap& map,
                             const Eigen::AlignedBox3d& region);

}  // namespace hexplore::planning
