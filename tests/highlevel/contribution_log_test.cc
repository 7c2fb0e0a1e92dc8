// What a robot's contribution log puts on the radio: every change of a supervoxel's coverage or
// traversability at once, a covered one's geometry drift at most once every few windows.
#include <gtest/gtest.h>

#include "common/highlevel/contribution_log.h"

namespace hexplore::highlevel {
namespace {

constexpr uint64_t kKey = 42;

Supervoxel ground(int voxels, bool covered = false) {
  Supervoxel s;
  s.key = kKey;
  s.surface = SurfaceClass::kGround;
  s.traversal_requirement = 1;
  s.voxel_count = voxels;
  s.covered = covered;
  return s;
}

MapUpdate upsert(const Supervoxel& s) {
  MapUpdate u;
  u.upserts.push_back(s);
  return u;
}

// The voxel count of the supervoxel each increment carries; 0 when it carries none.
int carried_count(const SourcedUpdate& inc) { return inc.update.upserts.empty() ? 0 : inc.update.upserts[0].voxel_count; }

TEST(ContributionLog, ACoveredSupervoxelsGeometryDriftWaitsForItsResendWindow) {
  ContributionLog log("r1");  // geometry_resend_windows = 3
  log.record(upsert(ground(10, /*covered=*/true)));
  EXPECT_EQ(carried_count(log.take_increment()), 10);  // seq 1
  log.record(upsert(ground(20, true)));                 // twice the voxels: past the tolerance
  EXPECT_EQ(carried_count(log.take_increment()), 0);   // seq 2: held
  EXPECT_EQ(log.snapshot().update.upserts.at(0).voxel_count, 10);  // peers hold the sent state
  EXPECT_EQ(carried_count(log.take_increment()), 0);   // seq 3: held, nothing new recorded
  EXPECT_EQ(carried_count(log.take_increment()), 20);  // seq 4: three windows after the last send
  EXPECT_EQ(carried_count(log.take_increment()), 0);   // sent once only
  EXPECT_EQ(log.snapshot().update.upserts.at(0).voxel_count, 20);
}

TEST(ContributionLog, AnIncompleteSupervoxelsGeometryGoesOutInTheNextWindow) {
  // Views aim at an incomplete supervoxel's centre and normal: a held one would send the next
  // look where its unseen part was windows ago.
  ContributionLog log("r1");
  log.record(upsert(ground(10)));
  log.take_increment();
  log.record(upsert(ground(20)));
  EXPECT_EQ(carried_count(log.take_increment()), 20);
}

TEST(ContributionLog, CoverageChangesGoOutInTheNextWindowEvenWhileGeometryWaits) {
  ContributionLog log("r1");
  log.record(upsert(ground(10)));
  log.take_increment();
  log.record(upsert(ground(11, /*covered=*/true)));
  const SourcedUpdate inc = log.take_increment();
  ASSERT_EQ(inc.update.upserts.size(), 1u);
  EXPECT_TRUE(inc.update.upserts[0].covered);
}

TEST(ContributionLog, DriftBelowTheToleranceIsNeverSent) {
  ContributionLog log("r1");
  log.record(upsert(ground(10)));
  log.take_increment();
  log.record(upsert(ground(11)));
  for (int window = 0; window < 5; ++window) EXPECT_EQ(carried_count(log.take_increment()), 0);
}

TEST(ContributionLog, AResendWindowOfOneSendsEveryWindow) {
  PublishTolerance every_window;
  every_window.geometry_resend_windows = 1;
  ContributionLog log("r1", 0, every_window);
  log.record(upsert(ground(10, true)));
  log.take_increment();
  log.record(upsert(ground(20, true)));
  EXPECT_EQ(carried_count(log.take_increment()), 20);
}

TEST(ContributionLog, ARemovalIsSentAtOnceAndAReturningKeyIsNew) {
  ContributionLog log("r1");
  log.record(upsert(ground(10)));
  log.take_increment();
  MapUpdate removal;
  removal.removals.push_back(kKey);
  log.record(removal);
  EXPECT_EQ(log.take_increment().update.removals, std::vector<uint64_t>{kKey});
  log.record(upsert(ground(30)));
  EXPECT_EQ(carried_count(log.take_increment()), 30);
}

}  // namespace
}  // namespace hexplore::highlevel
