// The per-round trace line (--trace-dir): what tools/report/route_churn.py reads from it.
#include "common/planning/round_trace.h"

#include <gtest/gtest.h>

#include "common/core/coverage_gap.h"
#include "common/highlevel/high_level_map.h"

namespace hexplore::planning {
namespace {

TEST(RoundTrace, OneLineWithTheRouteTheReferenceAndWhereTheFollowerHeads) {
  const highlevel::HighLevelMap map;
  PlanRequest req;
  req.map = &map;
  req.robots.resize(1);
  PlanResult res;
  res.reference_source = "mr1000a";
  res.robots.resize(1);
  TaskView v;
  v.position = {1.0, 2.0, 0.0};
  v.facade = true;
  v.targets = {7, 8};
  res.robots[0].route = {v};
  res.robots[0].cost_s = 40.0;
  res.robots[0].private_cost_s = 25.0;
  FollowerCounters f;
  f.legs_kept = 4;
  f.stretch_views_kept = 3;
  RoundTrace round;
  round.t_s = 12.5;
  round.reason = "route timed out";
  round.follower_next = {{3.0, 4.0, 0.0}, {5.0, 6.0, 0.0}};
  TargetJudgement judged;
  judged.target = 77;
  judged.voxels = 12;
  judged.covered_voxels = 9;
  judged.gap = int(core::CoverageGap::kAngle);
  judged.distance_m = 6.5;
  judged.incidence_deg = 51.2;
  judged.elevation_deg = 20.0;
  round.judged = {judged};
  const std::string line = round_trace_json(round, req, res, f, map, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-10),
                                                                                       Eigen::Vector3d::Constant(10)));
  ASSERT_FALSE(line.empty());
  EXPECT_EQ(line.back(), '\n');
  EXPECT_EQ(line.find('\n'), line.size() - 1);  // one line
  EXPECT_NE(line.find("\"t\": 12.5"), std::string::npos);
  EXPECT_NE(line.find("\"reference\": \"mr1000a\""), std::string::npos);
  EXPECT_NE(line.find("\"cost_s_per_robot\": [40], \"private_cost_s_per_robot\": [25]"), std::string::npos) << line;
  EXPECT_NE(line.find("\"route\": [{\"p\": [1.00, 2.00, 0.00], \"facade\": 1, \"targets\": 2}]"), std::string::npos);
  EXPECT_NE(line.find("\"legs_kept\": 4, \"legs_switched\": 0, \"stretch_views_kept\": 3"), std::string::npos);
  EXPECT_NE(line.find("\"next\": [[3.00, 4.00, 0.00], [5.00, 6.00, 0.00]]}"), std::string::npos) << line;
  EXPECT_NE(line.find("\"judged\": [{\"target\": 77, \"complete\": 0, \"voxels\": 12, \"covered\": 9, \"gap\": \"angle\", "
                      "\"distance_m\": 6.50, \"incidence_deg\": 51.2, \"elevation_deg\": 20.0}]}"),
            std::string::npos) << line;
}

}  // namespace
}  // namespace hexplore::planning
