#include "services/planning/fused_map_order.h"

#include <gtest/gtest.h>

namespace hexplore::planning_service {
namespace {

using Action = FusedMapOrder::Action;

TEST(FusedMapOrder, IncrementsApplyInOrderAndAGapAsksForTheWholeMap) {
  FusedMapOrder order;
  EXPECT_EQ(order.on_update(100, 3, false), Action::kRequestSnapshot);  // nothing held yet
  EXPECT_EQ(order.on_update(100, 3, true), Action::kApply);
  order.applied(100, 3);
  EXPECT_EQ(order.on_update(100, 4, false), Action::kApply);
  order.applied(100, 4);
  EXPECT_EQ(order.on_update(100, 4, false), Action::kDrop);             // a repeat
  EXPECT_EQ(order.on_update(100, 6, false), Action::kRequestSnapshot);  // 5 was lost
  EXPECT_EQ(order.on_update(100, 2, true), Action::kDrop);              // an older snapshot
}

// A restarted hlmap counts versions from 1 again: its first increment asks for its snapshot,
// the snapshot replaces the old map although its version is smaller, and whatever of the old
// run still arrives is dropped.
TEST(FusedMapOrder, ARestartedHlmapsMapReplacesTheOldOne) {
  FusedMapOrder order;
  order.applied(100, 500);
  EXPECT_EQ(order.on_update(200, 1, false), Action::kRequestSnapshot);
  EXPECT_EQ(order.on_update(200, 2, true), Action::kApply);
  order.applied(200, 2);
  EXPECT_EQ(order.version(), 2u);
  EXPECT_EQ(order.on_update(200, 3, false), Action::kApply);
  EXPECT_EQ(order.on_update(100, 501, false), Action::kDrop);
  EXPECT_EQ(order.on_update(100, 501, true), Action::kDrop);
}

}  // namespace
}  // namespace hexplore::planning_service
