#include "common/safety/polyline.h"

#include <gtest/gtest.h>

namespace hexplore::safety {
namespace {

using V = Eigen::Vector3d;

TEST(Polyline, LengthIsHorizontal) {
  EXPECT_DOUBLE_EQ(path_length({V(0, 0, 0), V(3, 4, 0), V(3, 4, 10)}), 5.0);
  EXPECT_DOUBLE_EQ(path_length({}), 0.0);
}

TEST(Polyline, RemainingPathStartsAtTheRobotAndSkipsWhatIsBehind) {
  const Path plan{V(0, 0, 0), V(4, 0, 0), V(4, 4, 0)};
  const Path rest = remaining_path(V(2, 0.5, 0), plan);
  ASSERT_EQ(rest.size(), 4u);
  EXPECT_TRUE(rest[0].isApprox(V(2, 0.5, 0)));
  EXPECT_TRUE(rest[1].isApprox(V(2, 0, 0)));
  EXPECT_TRUE(rest[2].isApprox(V(4, 0, 0)));
  EXPECT_TRUE(rest[3].isApprox(V(4, 4, 0)));
}

TEST(Polyline, WindowedProgressDoesNotJumpToANearbyLaterPart) {
  // A U-shaped path whose return leg passes 0.6 m from the outbound leg (a wall between).
  const Path plan{V(0, 0, 0), V(10, 0, 0), V(10, 0.6, 0), V(0, 0.6, 0)};
  const V robot(3, 0.35, 0);  // drifted towards the return leg
  double at = -1;
  const Path tracked = remaining_path(robot, plan, 2.5, 5.0, &at);
  EXPECT_NEAR(at, 3.0, 1e-9);
  EXPECT_TRUE(tracked[1].isApprox(V(3, 0, 0)));
  EXPECT_EQ(tracked.size(), 5u);
  const Path anywhere = remaining_path(robot, plan);
  EXPECT_TRUE(anywhere[1].isApprox(V(3, 0.6, 0)));  // what an untracked projection would do
}

TEST(Polyline, TruncateToEtaP) {
  const Path plan{V(0, 0, 0), V(1, 0, 0), V(1, 5, 0)};
  const Path near = truncate_to_length(plan, 2.0);
  EXPECT_NEAR(path_length(near), 2.0, 1e-9);
  EXPECT_TRUE(near.back().isApprox(V(1, 1, 0)));
  EXPECT_EQ(truncate_to_length(plan, 100.0).size(), 3u);
  EXPECT_EQ(truncate_to_length(plan, 0.0).size(), 1u);
}

TEST(Polyline, SamplesCoverBothEnds) {
  const Path plan{V(0, 0, 0), V(1.05, 0, 0)};
  const auto samples = sample_path(plan, 0.5);
  ASSERT_EQ(samples.size(), 4u);
  EXPECT_DOUBLE_EQ(samples.back().s_m, 1.05);
  EXPECT_TRUE(point_at(plan, 0.5).isApprox(V(0.5, 0, 0)));
  EXPECT_TRUE(direction_at(plan, 0.2).isApprox(V(1, 0, 0)));
  EXPECT_TRUE(extend_path(plan, 1.0).back().isApprox(V(2.05, 0, 0)));
}

}  // namespace
}  // namespace hexplore::safety
