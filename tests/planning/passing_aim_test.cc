// Where a gimbal looks on the way: the first target ahead on the route that passes J from
// here, held for a few scans, dropped after its budget of looks; never one behind a wall, out
// of range, complete or given up.
#include "common/planning/passing_aim.h"

#include <gtest/gtest.h>

#include <vector>

namespace hexplore::planning {
namespace {

highlevel::Supervoxel facade(uint64_t key, const Eigen::Vector3d& c, const Eigen::Vector3d& n) {
  highlevel::Supervoxel s;
  s.key = key;
  s.center = c;
  s.normal = n;
  s.surface = highlevel::SurfaceClass::kFacade;
  s.voxel_count = 40;
  return s;
}

struct World {
  highlevel::HighLevelMap map{{2, 1}};
  GiveUpLedger ledger;
  PlannerOptions planner;
  PassingAimOptions aim;
  World() {
    // A wall at y = 5 facing -y: patch 1 straight ahead of a robot at the origin, patch 2 to
    // the side (about 40 deg off its normal from there), patch 3 far to the side (beyond J
    // and range).
    map.apply(highlevel::MapUpdate{.upserts = {facade(1, {0, 5, 0.8}, {0, -1, 0}), facade(2, {4, 5, 0.8}, {0, -1, 0}),
                                               facade(3, {12, 5, 0.8}, {0, -1, 0})}});
    aim.range_m = 10.0;
    aim.hold_s = 2.0;
    aim.budget_s = 4.0;
  }
};

TEST(PassingAim, LooksAtTheFirstTargetAheadInViewAndHoldsItForTheHoldTime) {
  World w;
  PassingAim a(w.aim, w.planner);
  const std::vector<uint64_t> ahead = {3, 2, 1};
  ASSERT_TRUE(a.step(0.0, {0, 0, 0}, w.map, w.ledger, ahead).has_value());
  EXPECT_EQ(a.target(), 2u);  // 3 is out of view; 2 comes before 1 on the route
  // Patch 2 drops out of J from (-4, 0): patch 1 takes over at once.
  a.step(1.0, {-4, 0, 0}, w.map, w.ledger, ahead);
  EXPECT_EQ(a.target(), 1u);
  // Back where both are in view: patch 1 is held for 2 s, then the route order wins again.
  a.step(2.0, {0, 0, 0}, w.map, w.ledger, ahead);
  EXPECT_EQ(a.target(), 1u);
  a.step(3.0, {0, 0, 0}, w.map, w.ledger, ahead);
  EXPECT_EQ(a.target(), 2u);
  EXPECT_EQ(a.aims(), 3);
}

TEST(PassingAim, GivesATargetAtMostItsBudgetOfLooks) {
  World w;
  PassingAim a(w.aim, w.planner);
  const std::vector<uint64_t> ahead = {1, 2};
  for (double t = 0.0; t <= 4.0; t += 1.0) a.step(t, {0, 0, 0}, w.map, w.ledger, ahead);
  // Four seconds on patch 1 spend its budget: the next target ahead takes over.
  EXPECT_EQ(a.target(), 2u);
}

TEST(PassingAim, NeverLooksAtWhatIsCompleteGivenUpHiddenOrOutOfRange) {
  World w;
  const std::vector<uint64_t> ahead = {1, 2};
  highlevel::Supervoxel done = *w.map.find(1);
  done.covered = true;
  w.map.apply(highlevel::MapUpdate{.upserts = {done}});
  PassingAim a(w.aim, w.planner);
  a.step(0.0, {0, 0, 0}, w.map, w.ledger, ahead);
  EXPECT_EQ(a.target(), 2u);  // patch 1 is complete

  // Patch 2 given up (two distinct spots): nothing ahead passes J from here.
  w.ledger.observed(2, {4, 0, 0}, 40);
  w.ledger.observed(2, {4, 3, 0}, 40);
  ASSERT_TRUE(w.ledger.given_up(2, 40));
  PassingAim b(w.aim, w.planner);
  EXPECT_FALSE(b.step(0.0, {0, 0, 0}, w.map, w.ledger, ahead).has_value());
  EXPECT_EQ(b.target(), 0u);

  // Out of range, and a target behind another patch (which faces away and is not ahead).
  World far;
  PassingAim c(far.aim, far.planner);
  EXPECT_FALSE(c.step(0.0, {0, -12, 0}, far.map, far.ledger, ahead).has_value());
  World hidden;
  hidden.map.apply(highlevel::MapUpdate{.upserts = {facade(4, {0, 9, 0.8}, {0, -1, 0}), facade(5, {0, 5, 0.8}, {1, 0, 0})}});
  PassingAim d(hidden.aim, hidden.planner);
  const std::vector<uint64_t> behind = {4};
  EXPECT_FALSE(d.step(0.0, {0, 0, 0}, hidden.map, hidden.ledger, behind).has_value());
}

}  // namespace
}  // namespace hexplore::planning
