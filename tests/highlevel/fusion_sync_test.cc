#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/peer_sync.h"
#include "common/highlevel/segmenter.h"
#include "tests/highlevel/synthetic_map.h"

namespace hexplore::highlevel {
namespace {

const std::vector<int> kLevels = {1, 2};

Supervoxel sv(uint64_t key, double x, int req, bool covered, Eigen::Vector3d normal) {
  Supervoxel s;
  s.key = key;
  s.center = {x, 0, 0};
  s.normal = normal.normalized();
  s.covered = covered;
  s.traversal_requirement = req;
  s.surface = SurfaceClass::kGround;
  s.voxel_count = 10;
  return s;
}

TEST(MapFusion, FusesByMaxOrAndAverage) {
  MapFusion fusion(kLevels);
  MapUpdate a;
  a.upserts = {sv(1, 0.0, 1, false, {0, 0, 1}), sv(2, 1.0, 1, false, {0, 0, 1}), sv(3, 2.0, 2, false, {0, 0, 1})};
  a.edge_upserts = {{1, 2}, {2, 3}};
  MapUpdate b;
  b.upserts = {sv(1, 0.2, 2, true, {0, 1, 1}), sv(3, 2.0, 0, false, {0, 0, 1})};
  b.edge_upserts = {{1, 2}};
  fusion.apply("a", a);
  fusion.apply("b", b);
  const HighLevelMap& m = fusion.map();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.find(1)->traversal_requirement, 2);  // maximum
  EXPECT_TRUE(m.find(1)->covered);                 // OR
  EXPECT_NEAR(m.find(1)->center.x(), 0.1, 1e-12);  // average
  EXPECT_NEAR(m.find(1)->normal.y(), m.find(1)->normal.z() * (1 / std::sqrt(2.0)) / (1 + 1 / std::sqrt(2.0)), 1e-9);
  EXPECT_EQ(m.find(3)->traversal_requirement, 0);  // N/A from one source is the strictest
  EXPECT_EQ(m.edges().size(), 2u);
  EXPECT_FALSE(m.graph().contains(3));
  // Removing a source's report falls back to the others.
  MapUpdate b2;
  b2.removals = {1};
  b2.edge_removals = {{1, 2}};
  fusion.apply("b", b2);
  EXPECT_EQ(m.find(1)->traversal_requirement, 1);
  EXPECT_EQ(m.edges().size(), 2u) << "source a still reports edge 1-2";
  fusion.remove_source("a");
  EXPECT_EQ(m.size(), 1u);
  EXPECT_TRUE(m.edges().empty());
}

TEST(MapFusion, AnIncompleteSupervoxelTakesTheFurthestSourcesGap) {
  MapFusion fusion(kLevels);
  Supervoxel a = sv(1, 0.0, 1, false, {0, 0, 1});
  a.covered_voxels = 3;
  a.gap = core::CoverageGap::kAngle;
  Supervoxel b = a;
  b.covered_voxels = 8;
  b.gap = core::CoverageGap::kDensity;
  fusion.apply("a", MapUpdate{.upserts = {a}});
  fusion.apply("b", MapUpdate{.upserts = {b}});
  EXPECT_EQ(fusion.map().find(1)->gap, core::CoverageGap::kDensity);
  EXPECT_EQ(fusion.map().find(1)->covered_voxels, 8);
  Supervoxel c = a;
  c.covered = true;
  c.covered_voxels = c.voxel_count;
  c.gap = core::CoverageGap::kNone;
  fusion.apply("c", MapUpdate{.upserts = {c}});
  EXPECT_TRUE(fusion.map().find(1)->covered);
  EXPECT_EQ(fusion.map().find(1)->gap, core::CoverageGap::kNone);
}

TEST(ProtoConvert, CoverageGapTravelsWithIncompleteSupervoxelsOnly) {
  Supervoxel s = sv(5, 1.0, 1, false, {0, 0, 1});
  s.covered_voxels = 7;
  s.gap = core::CoverageGap::kDistance;
  v1::Supervoxel m;
  to_proto(s, &m);
  const Supervoxel back = from_proto(m);
  EXPECT_EQ(back.gap, core::CoverageGap::kDistance);
  EXPECT_EQ(back.covered_voxels, 7);
  s.covered = true;
  v1::Supervoxel covered;
  to_proto(s, &covered);
  EXPECT_EQ(covered.covered_voxels(), 0u);  // not sent: covered says it all
  EXPECT_EQ(covered.coverage_gap(), v1::COVERAGE_GAP_NONE);
  EXPECT_EQ(from_proto(covered).covered_voxels, s.voxel_count);
  // A gap this build does not know (a newer peer) reads as "no reason given".
  m.set_coverage_gap(static_cast<v1::CoverageGap>(42));
  EXPECT_EQ(from_proto(m).gap, core::CoverageGap::kNone);
}

TEST(MapFusion, ResultDoesNotDependOnArrivalOrder) {
  // Three sources' increments, delivered in different interleavings.
  std::vector<SourcedUpdate> increments;
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> key(1, 40);
  std::uniform_int_distribution<int> req(0, 2);
  std::uniform_real_distribution<double> x(0, 10);
  for (const std::string src : {"r1", "r2", "r3"}) {
    for (uint64_t seq = 1; seq <= 15; ++seq) {
      SourcedUpdate inc{src, seq, {}};
      for (int i = 0; i < 6; ++i) inc.update.upserts.push_back(wire_rounded(sv(key(rng), x(rng), req(rng), i % 3 == 0, {x(rng), 1, 5})));
      inc.update.removals.push_back(key(rng));
      inc.update.edge_upserts.push_back(EdgeKey::of(key(rng), key(rng)));
      inc.update.edge_removals.push_back(EdgeKey::of(key(rng), key(rng)));
      increments.push_back(inc);
    }
  }
  auto run = [&](uint32_t seed) {
    // Per-source order is kept (sequence numbers), interleaving across sources is random.
    std::map<std::string, size_t> next;
    std::vector<const SourcedUpdate*> order;
    std::map<std::string, std::vector<const SourcedUpdate*>> per;
    for (const auto& inc : increments) per[inc.source].push_back(&inc);
    std::mt19937 r(seed);
    while (order.size() < increments.size()) {
      auto it = per.begin();
      std::advance(it, std::uniform_int_distribution<size_t>(0, per.size() - 1)(r));
      if (next[it->first] < it->second.size()) order.push_back(it->second[next[it->first]++]);
    }
    auto fusion = std::make_unique<MapFusion>(kLevels);
    for (const auto* inc : order) fusion->apply(inc->source, inc->update);
    return fusion;
  };
  const auto a = run(1);
  const auto b = run(2);
  const auto c = run(3);
  EXPECT_GT(a->map().size(), 10u);
  EXPECT_TRUE(same_map(a->map(), b->map()));
  EXPECT_TRUE(same_map(a->map(), c->map()));
}

TEST(PeerSync, DetectsGapsBuffersAndRepairs) {
  PeerSync sync("me", 1.0);
  auto inc = [](uint64_t seq) { return SourcedUpdate{"p", seq, {}}; };
  EXPECT_EQ(sync.on_increment(inc(1)).size(), 1u);
  EXPECT_EQ(sync.on_increment(inc(2)).size(), 1u);
  EXPECT_TRUE(sync.on_increment(inc(2)).empty());  // duplicate
  EXPECT_TRUE(sync.on_increment(inc(4)).empty());  // 3 lost: buffered
  EXPECT_TRUE(sync.on_increment(inc(5)).empty());
  EXPECT_EQ(sync.stats().gaps_detected, 1u);
  auto req = sync.due_requests(10.0);
  ASSERT_EQ(req.size(), 1u);
  EXPECT_EQ(req[0].source, "p");
  EXPECT_EQ(req[0].from_seq, 3u);
  EXPECT_TRUE(sync.due_requests(10.5).empty());      // waiting for the answer
  EXPECT_EQ(sync.due_requests(11.1).size(), 1u);     // no answer: asked again
  SourcedUpdate snap{"p", 3, {}};
  snap.update.full_snapshot = true;
  const auto ready = sync.on_snapshot(snap);
  ASSERT_EQ(ready.size(), 3u);  // snapshot, then buffered 4 and 5
  EXPECT_EQ(ready[1].seq, 4u);
  EXPECT_EQ(ready[2].seq, 5u);
  EXPECT_TRUE(sync.in_sync("p"));
  EXPECT_EQ(sync.stats().gaps_repaired, 1u);
  EXPECT_TRUE(sync.on_snapshot(SourcedUpdate{"p", 2, {}}).empty());  // stale
  EXPECT_TRUE(sync.on_increment(SourcedUpdate{"me", 1, {}}).empty());  // own echo
}

// A restarted source numbers from 1 again under a newer incarnation: its old contribution is
// voided whether or not its increment 1 arrives, and nothing of the old run applies after.
TEST(PeerSync, ARestartedSourceReplacesItsContribution) {
  auto update = [](uint64_t incarnation, uint64_t seq, bool snapshot = false) {
    SourcedUpdate u{"p", seq, {}, incarnation};
    u.update.full_snapshot = snapshot;
    return u;
  };
  {
    PeerSync sync("me", 1.0);
    for (uint64_t seq = 1; seq <= 40; ++seq) ASSERT_EQ(sync.on_increment(update(100, seq)).size(), 1u);
    // Increment 1 of the new run arrives: the old contribution is void, then 1 applies.
    const auto ready = sync.on_increment(update(200, 1));
    ASSERT_EQ(ready.size(), 2u);
    EXPECT_TRUE(ready[0].update.full_snapshot);
    EXPECT_TRUE(ready[0].update.upserts.empty());
    EXPECT_EQ(ready[1].seq, 1u);
    EXPECT_EQ(sync.stats().restarts, 1u);
    EXPECT_TRUE(sync.in_sync("p"));
    EXPECT_EQ(sync.incarnation("p"), 200u);
  }
  PeerSync sync("me", 1.0);
  for (uint64_t seq = 1; seq <= 40; ++seq) ASSERT_EQ(sync.on_increment(update(100, seq)).size(), 1u);
  // Increment 1 was lost (a subscriber reconnects after the restart): increment 2 of the new
  // run voids the old contribution and asks for the new one whole, although 2 <= 40.
  const auto ready = sync.on_increment(update(200, 2));
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_TRUE(ready[0].update.full_snapshot);
  EXPECT_EQ(sync.applied_seq("p"), 0u);
  const auto requests = sync.due_requests(5.0);
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].from_seq, 0u);
  // Whatever of the old run is still on its way is dropped: a late increment, a relayed snapshot.
  EXPECT_TRUE(sync.on_increment(update(100, 41)).empty());
  EXPECT_TRUE(sync.on_snapshot(update(100, 41, true)).empty());
  EXPECT_EQ(sync.stats().stale, 2u);
  // The new run's snapshot, then its buffered increment 2 is superseded and 3 follows.
  const auto repaired = sync.on_snapshot(update(200, 2, true));
  ASSERT_EQ(repaired.size(), 1u);
  EXPECT_EQ(repaired[0].incarnation, 200u);
  EXPECT_EQ(sync.on_increment(update(200, 3)).size(), 1u);
  EXPECT_TRUE(sync.in_sync("p"));
  EXPECT_EQ(sync.stats().restarts, 1u);
}

TEST(PeerSync, LateJoinerAsksForSnapshots) {
  PeerSync sync("late", 1.0);
  sync.want_snapshot("p");
  auto req = sync.due_requests(0.0);
  ASSERT_EQ(req.size(), 1u);
  EXPECT_EQ(req[0].from_seq, 0u);
  EXPECT_TRUE(sync.on_increment(SourcedUpdate{"p", 9, {}}).empty());
  SourcedUpdate snap{"p", 8, {}};
  snap.update.full_snapshot = true;
  EXPECT_EQ(sync.on_snapshot(snap).size(), 2u);
  EXPECT_TRUE(sync.in_sync("p"));
}

// Library-level team: segmenter + contribution log + fusion + peer sync per robot, a lossy
// "network" that serialises every message through the wire protos, and repair by snapshot.
class TeamSim {
 public:
  struct Robot {
    std::string id;
    SupervoxelSegmenter seg{{}, kLevels};
    ContributionLog log;
    MapFusion fusion{kLevels};
    PeerSync sync;
    bool online = false;
    std::vector<VoxelSample> sensed;  // what its mapping holds (a restarted hlmap gets it all again)
    Robot(const std::string& name, uint64_t incarnation) : id(name), log(name, incarnation), sync(name, 1.0) {}
  };

  TeamSim(int robots, double drop, uint32_t seed) : drop_(drop), rng_(seed) {
    for (int i = 0; i < robots; ++i) robots_.push_back(std::make_unique<Robot>("r" + std::to_string(i + 1), 1));
  }
  Robot& robot(int i) { return *robots_[i]; }

  void join(int i) {
    Robot& r = *robots_[i];
    r.online = true;
    for (const auto& other : robots_)
      if (other->id != r.id) r.sync.want_snapshot(other->id);
  }
  void sense(int i, std::span<const VoxelSample> voxels) {
    Robot& r = *robots_[i];
    const auto change = r.seg.update(voxels);
    r.log.record(r.seg, change);
    r.sensed.insert(r.sensed.end(), voxels.begin(), voxels.end());
  }
  // Robot i's hlmap restarts under a new incarnation: it starts empty, its mapping hands it
  // everything sensed so far, and (`lose_first`) no peer receives its first increment, as
  // when subscribers reconnect to the new process only after it published.
  void restart(int i, uint64_t incarnation, bool lose_first) {
    auto fresh = std::make_unique<Robot>(robots_[i]->id, incarnation);
    const std::vector<VoxelSample> sensed = std::move(robots_[i]->sensed);
    robots_[i] = std::move(fresh);
    join(i);
    sense(i, sensed);
    lose_next_from_ = lose_first ? robots_[i].get() : nullptr;
  }
  bool lost() { return std::uniform_real_distribution<double>(0, 1)(rng_) < drop_; }

  // One eta_c window: everyone publishes, the lossy network delivers, repairs run.
  void window() {
    now_ += 1.0;
    for (auto& src : robots_) {
      if (!src->online) continue;
      const auto inc = src->log.take_increment();
      src->fusion.apply(src->id, inc.update);
      const std::string wire = to_increment(inc, src->log.contribution()).SerializeAsString();
      bytes_ += wire.size();
      const bool lose = lose_next_from_ == src.get();
      if (lose) lose_next_from_ = nullptr;
      for (auto& dst : robots_) {
        if (dst == src || !dst->online || lost() || lose) continue;
        v1::MapIncrement m;
        ASSERT_TRUE(m.ParseFromString(wire));
        for (auto& ready : dst->sync.on_increment(from_proto(m))) dst->fusion.apply(ready.source, ready.update);
      }
    }
    for (auto& dst : robots_) {
      if (!dst->online) continue;
      for (const auto& req : dst->sync.due_requests(now_)) {
        Robot* src = find(req.source);
        if (src == nullptr || !src->online || lost() || lost()) continue;  // request or reply lost
        const std::string wire = to_snapshot(src->log.snapshot(), src->log.contribution()).SerializeAsString();
        repair_bytes_ += wire.size();
        v1::MapSnapshot m;
        ASSERT_TRUE(m.ParseFromString(wire));
        for (auto& ready : dst->sync.on_snapshot(from_proto(m))) dst->fusion.apply(ready.source, ready.update);
      }
    }
  }
  bool converged() const {
    for (const auto& r : robots_) {
      if (!r->online) continue;
      for (const auto& o : robots_)
        if (o != r && o->online && !r->sync.in_sync(o->id)) return false;
      if (!same_map(r->fusion.map(), robots_[0]->fusion.map())) return false;
    }
    return true;
  }
  // What every robot should hold: the fusion of everyone's current contribution.
  std::unique_ptr<MapFusion> reference() const {
    auto f = std::make_unique<MapFusion>(kLevels);
    for (const auto& r : robots_) f->apply(r->id, r->log.snapshot().update);
    return f;
  }
  size_t bytes() const { return bytes_; }
  size_t repair_bytes() const { return repair_bytes_; }

 private:
  Robot* find(const std::string& id) {
    for (auto& r : robots_)
      if (r->id == id) return r.get();
    return nullptr;
  }
  std::vector<std::unique_ptr<Robot>> robots_;
  double drop_;
  std::mt19937 rng_;
  double now_ = 0.0;
  size_t bytes_ = 0;
  size_t repair_bytes_ = 0;
  const Robot* lose_next_from_ = nullptr;
};

using testing::overlapping_streams;

void run_team(TeamSim& team, const std::vector<std::vector<VoxelSample>>& streams, int late_robot, int windows) {
  const int n = static_cast<int>(streams.size());
  for (int i = 0; i < n; ++i)
    if (i != late_robot) team.join(i);
  for (int w = 0; w < windows; ++w) {
    if (w == windows / 2 && late_robot >= 0) team.join(late_robot);
    for (int i = 0; i < n; ++i) {
      if (i == late_robot && w < windows / 2) continue;
      const auto& s = streams[i];
      const size_t chunk = (s.size() + windows - 1) / windows;
      const size_t begin = std::min(s.size(), chunk * (i == late_robot ? (w - windows / 2) * 2 : w));
      const size_t end = std::min(s.size(), begin + chunk * (i == late_robot ? 2 : 1));
      team.sense(i, std::span(s.data() + begin, end - begin));
    }
    team.window();
  }
}

TEST(TeamSync, MapsConvergeWithoutLoss) {
  const auto streams = overlapping_streams(3, 1);
  TeamSim team(3, 0.0, 1);
  run_team(team, streams, -1, 10);
  team.window();
  ASSERT_TRUE(team.converged());
  const auto ref = team.reference();
  EXPECT_TRUE(same_map(team.robot(0).fusion.map(), ref->map()));
  EXPECT_GT(ref->map().size(), 200u);
  EXPECT_GT(ref->map().graph().edge_count(), 300u);
}

TEST(TeamSync, MapsConvergeAfterRepairWithThirtyPercentLoss) {
  const auto streams = overlapping_streams(3, 2);
  for (uint32_t seed : {3u, 4u, 5u}) {
    TeamSim team(3, 0.3, seed);
    run_team(team, streams, -1, 12);
    int extra = 0;
    while (!team.converged() && extra < 30) {
      team.window();
      ++extra;
    }
    ASSERT_TRUE(team.converged()) << "seed " << seed;
    const auto ref = team.reference();
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_map(team.robot(i).fusion.map(), ref->map()));
    uint64_t gaps = 0;
    for (int i = 0; i < 3; ++i) gaps += team.robot(i).sync.stats().gaps_detected;
    EXPECT_GT(gaps, 0u) << "loss must have caused gaps";
  }
}

TEST(TeamSync, LateJoinerReceivesTheWholeMap) {
  const auto streams = overlapping_streams(3, 3);
  TeamSim team(3, 0.3, 9);
  run_team(team, streams, 2, 12);
  int extra = 0;
  while (!team.converged() && extra < 30) {
    team.window();
    ++extra;
  }
  ASSERT_TRUE(team.converged());
  const auto ref = team.reference();
  EXPECT_TRUE(same_map(team.robot(2).fusion.map(), ref->map()));
  EXPECT_GT(team.robot(2).fusion.contribution("r1")->supervoxels.size(), 50u);
}

// A robot's hlmap restarts long after the mission began (its increment numbering starts at 1
// again) and senses more: every teammate ends up with its new contribution, in a few windows,
// also when the first increment of the new run is lost.
TEST(TeamSync, TeammatesTakeARestartedHlmapsNewContribution) {
  const auto streams = overlapping_streams(3, 6);
  const auto more = overlapping_streams(3, 7);  // the same ground seen again, other noise and coverage
  for (bool lose_first : {false, true}) {
    TeamSim team(3, 0.0, 12);
    run_team(team, streams, -1, 10);
    for (int w = 0; w < 30; ++w) team.window();  // increments numbered past 40
    ASSERT_TRUE(team.converged());
    team.restart(0, 2, lose_first);
    team.sense(0, more[0]);
    int windows = 0;
    while (!team.converged() && windows < 6) {
      team.window();
      ++windows;
    }
    ASSERT_TRUE(team.converged()) << (lose_first ? "increment 1 lost" : "increment 1 received");
    const auto ref = team.reference();
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_map(team.robot(i).fusion.map(), ref->map()));
    EXPECT_EQ(team.robot(1).sync.stats().restarts, 1u);
    EXPECT_EQ(team.robot(1).sync.incarnation("r1"), 2u);
  }
}

}  // namespace
}  // namespace hexplore::highlevel
