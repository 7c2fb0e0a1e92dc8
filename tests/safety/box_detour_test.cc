#include "common/safety/box_detour.h"

#include <gtest/gtest.h>

namespace hexplore::safety {
namespace {

using V = Eigen::Vector3d;

ObstacleBox box(const char* id, double x0, double y0, double x1, double y1) {
  return {id, Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y1)};
}

bool path_clear(const Path& path, const ObstacleBox& b) {
  for (size_t i = 1; i < path.size(); ++i) {
    if (b.intersects_segment(path[i - 1].head<2>(), path[i].head<2>())) return false;
  }
  return true;
}

TEST(BoxDetour, SegmentTests) {
  const auto b = box("x", -1, -1, 1, 1);
  EXPECT_TRUE(b.intersects_segment({-2, 0}, {2, 0}));
  EXPECT_FALSE(b.intersects_segment({-2, 1}, {2, 1}));  // along an edge is allowed
  EXPECT_FALSE(b.intersects_segment({-2, 2}, {2, 2}));
  EXPECT_TRUE(b.intersects_segment({0, 0}, {0, 0.5}));
  EXPECT_TRUE(b.contains({0.5, 0.5}));
  EXPECT_FALSE(b.contains({1, 0}));
}

TEST(BoxDetour, FreePathIsUnchanged) {
  const Path plan{V(-5, 3, 0), V(5, 3, 0)};
  const auto r = detour_around(plan, {box("b", -1, -1, 1, 1)}, {});
  EXPECT_FALSE(r.detoured);
  EXPECT_FALSE(r.blocked);
  EXPECT_EQ(r.path, plan);
}

TEST(BoxDetour, GoesAroundABoxOnThePathAndRejoins) {
  const Path plan{V(-5, 0.1, 0), V(5, 0.1, 0)};
  const auto b = box("b", -1, -1, 1, 1);
  const auto r = detour_around(plan, {b}, {});
  EXPECT_TRUE(r.detoured);
  EXPECT_FALSE(r.blocked);
  EXPECT_TRUE(path_clear(r.path, b));
  EXPECT_TRUE(r.path.back().isApprox(plan.back()));
  EXPECT_TRUE(r.path.front().isApprox(plan.front()));
  // Short way round: the detour passes on the near side (+y, since the path is at y = 0.1).
  double max_y = -10;
  for (const auto& p : r.path) max_y = std::max(max_y, p.y());
  EXPECT_NEAR(max_y, 1.2, 1e-6);
  EXPECT_LT(path_length(r.path), 10.0 + 2.0 * 1.3 + 0.5);
}

TEST(BoxDetour, TwoBoxesInARow) {
  const Path plan{V(-6, 0, 0), V(6, 0, 0)};
  const auto b1 = box("a", -3, -1, -2, 1);
  const auto b2 = box("c", 2, -1, 3, 1);
  const auto r = detour_around(plan, {b1, b2}, {});
  EXPECT_TRUE(r.detoured);
  EXPECT_TRUE(path_clear(r.path, b1));
  EXPECT_TRUE(path_clear(r.path, b2));
  EXPECT_TRUE(r.path.back().isApprox(plan.back()));
}

TEST(BoxDetour, GoalInsideABoxStopsBeforeIt) {
  const Path plan{V(-5, 0, 0), V(0, 0, 0)};
  const auto r = detour_around(plan, {box("b", -1, -1, 1, 1)}, {});
  EXPECT_TRUE(r.blocked);
  EXPECT_EQ(r.blocked_by, "b");
  EXPECT_LE(r.path.back().x(), -1.0);
  EXPECT_GT(r.path.back().x(), -1.2);
}

TEST(BoxDetour, RobotInsideABoxMayLeaveButNotGoDeeper) {
  // Robot at x = -0.9 inside [-1, 1]: moving away (-x) is fine, towards the centre is cut.
  const auto b = box("b", -1, -1, 1, 1);
  const auto away = detour_around({V(-0.9, 0, 0), V(-5, 0, 0)}, {b}, {});
  EXPECT_FALSE(away.blocked);
  EXPECT_TRUE(away.path.back().isApprox(V(-5, 0, 0)));
  const auto deeper = detour_around({V(-0.9, 0, 0), V(0.0, 0, 0)}, {b}, {});
  EXPECT_TRUE(deeper.blocked);
  EXPECT_LT(path_length(deeper.path), 0.05);
}

}  // namespace
}  // namespace hexplore::safety
