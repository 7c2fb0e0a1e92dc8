#include "common/safety/conflict.h"

#include <gtest/gtest.h>

namespace hexplore::safety {
namespace {

using V = Eigen::Vector3d;

TEST(Conflict, CrossingPathsGiveEntriesOnBoth) {
  const Path a{V(-3, 0, 0), V(3, 0, 0)};
  const Path b{V(0, -2, 0), V(0, 2, 0)};
  const auto c = find_conflict(a, b, 1.0, 0.05);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->kind, ConflictKind::kCrossing);
  EXPECT_NEAR(c->own_entry_m, 2.0, 0.06);
  EXPECT_NEAR(c->peer_entry_m, 1.0, 0.06);
  // Symmetric: swapping the paths swaps the entries.
  const auto d = find_conflict(b, a, 1.0, 0.05);
  ASSERT_TRUE(d.has_value());
  EXPECT_DOUBLE_EQ(d->own_entry_m, c->peer_entry_m);
  EXPECT_DOUBLE_EQ(d->peer_entry_m, c->own_entry_m);
}

TEST(Conflict, HeadOnAndFollowing) {
  const Path a{V(0, 0, 0), V(2, 0, 0)};
  const auto head_on = find_conflict(a, {V(4, 0.2, 0), V(2.5, 0.2, 0)}, 1.0, 0.1);
  ASSERT_TRUE(head_on.has_value());
  EXPECT_EQ(head_on->kind, ConflictKind::kHeadOn);
  const auto following = find_conflict(a, {V(2.5, 0, 0), V(4.5, 0, 0)}, 1.0, 0.1);
  ASSERT_TRUE(following.has_value());
  EXPECT_EQ(following->kind, ConflictKind::kFollowing);
  EXPECT_NEAR(following->peer_entry_m, 0.0, 1e-9);  // the robot ahead is already in the zone
}

TEST(Conflict, ParallelPathsFarApartDoNotConflict) {
  EXPECT_FALSE(find_conflict({V(0, 0, 0), V(5, 0, 0)}, {V(0, 1.5, 0), V(5, 1.5, 0)}, 1.2, 0.1).has_value());
  EXPECT_TRUE(find_conflict({V(0, 0, 0), V(5, 0, 0)}, {V(0, 1.0, 0), V(5, 1.0, 0)}, 1.2, 0.1).has_value());
}

TEST(Conflict, TimeToReach) {
  EXPECT_DOUBLE_EQ(time_to_reach(2.0, 0.5), 4.0);
  EXPECT_TRUE(std::isinf(time_to_reach(2.0, 0.0)));
}

}  // namespace
}  // namespace hexplore::safety
