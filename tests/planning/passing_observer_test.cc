// Observations on the way: a target kept in view from one spot for the dwell counts as an
// observation once it has settled; one out of range, behind a wall or only glimpsed does not.
#include "common/planning/passing_observer.h"

#include <gtest/gtest.h>

#include "common/core/team_config.h"

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
  core::TeamConfig team;
  highlevel::HighLevelMap map{{2, 1}};
  GiveUpLedger ledger{GiveUpRules{.views = 2}};  // two looks: a first look is judged without giving up
  PlannerOptions planner;
  PassingOptions passing;
  World() {
    // A wall patch at y = 5 facing -y, and a second one hidden behind an occluding patch.
    map.apply(highlevel::MapUpdate{.upserts = {facade(1, {0, 5, 0.8}, {0, -1, 0}), facade(2, {8, 5, 0.8}, {0, -1, 0}),
                                               facade(3, {8, 3, 0.8}, {0, -1, 0})}});
    passing.range_m = 10.0;
    passing.dwell_s = 1.0;
    passing.settle_s = 2.0;
  }
};

TEST(PassingObserver, ATargetKeptInViewCountsOnceSettled) {
  World w;
  PassingObserver o(w.passing, w.planner);
  for (double t = 0.0; t <= 1.0; t += 0.5) o.step(t, {0, 1, 0.2}, w.map, w.ledger);
  EXPECT_EQ(w.ledger.attempts(1), 0);  // seen long enough, not settled yet
  o.step(3.5, {0, 1, 0.2}, w.map, w.ledger);
  EXPECT_EQ(w.ledger.attempts(1), 1);
  EXPECT_EQ(o.observations(), 1);
  // Patch 2 sits behind patch 3 (same line of sight), patch 3 was out of the cone: nothing.
  EXPECT_EQ(w.ledger.attempts(2), 0);
}

TEST(PassingObserver, AGlimpseAFarTargetOrACompletedOneDoesNotCount) {
  World w;
  PassingObserver o(w.passing, w.planner);
  // Driving past: each look from a new spot (more than spot_m on), never a second in view.
  for (double t = 0.0, x = -6.0; t <= 8.0; t += 1.0, x += 1.6) o.step(t, {x, 1, 0.2}, w.map, w.ledger);
  o.step(12.0, {20, 1, 0.2}, w.map, w.ledger);
  EXPECT_EQ(w.ledger.attempts(1), 0);
  // Out of range.
  PassingObserver far(w.passing, w.planner);
  for (double t = 0.0; t <= 5.0; t += 0.5) far.step(t, {0, -8, 0.2}, w.map, w.ledger);
  EXPECT_EQ(w.ledger.attempts(1), 0);
  // Completed before it is judged.
  PassingObserver done(w.passing, w.planner);
  for (double t = 0.0; t <= 1.5; t += 0.5) done.step(t, {0, 1, 0.2}, w.map, w.ledger);
  highlevel::Supervoxel c = *w.map.find(1);
  c.covered = true;
  w.map.apply(highlevel::MapUpdate{.upserts = {c}});
  done.step(4.0, {0, 1, 0.2}, w.map, w.ledger);
  EXPECT_EQ(w.ledger.attempts(1), 0);
}

}  // namespace
}  // namespace hexplore::planning
