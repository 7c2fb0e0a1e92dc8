#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/core/team_config.h"
#include "common/evaluation/record_checkpoint.h"
#include "common/evaluation/team_recorder.h"
#include "tests/evaluation/status_fixture.h"
#include "common/evaluation/results_writer.h"

namespace hexplore::evaluation {
namespace {

core::TeamConfig team(const std::string& robots = "[{id: a, species: SLUGCAT}, {id: b, species: MR1000}]") {
  return core::parse_team_config(
      "scene: small-building\nspecies: [{builtin: SLUGCAT}, {builtin: MR1000}]\nrobots: " + robots + "\n", "test");
}

v1::RobotPose pose_at(double x, double y) {
  v1::RobotPose p;
  p.mutable_pose()->mutable_position_m()->set_x(x);
  p.mutable_pose()->mutable_position_m()->set_y(y);
  return p;
}

using testing::status;

// What the station hears in sim second `t` of a mission that started at sim time 100 s.
void hear_second(TeamRecorder& r, int t) {
  const double now = 100.0 + t;
  r.on_pose("a", now, pose_at(t, 0.0));
  r.on_pose("b", now, pose_at(0.0, 2.0 * t));
  r.on_team_message("a", "team/map", 100 + t);
  r.on_team_message("b", "team/plan", 30);
  r.on_status("a", "sim", status({{"odometry_m", 50.0 + t}, {"collisions", 1.0 + (t >= 15 ? 1 : 0)}}));
  r.on_status("b", "hlmap", status({{"gaps_detected", 3.0 + t / 5}, {"own_increment_seq", 10.0 + t},
                                    {"in_sync.a", t >= 3 && t <= 12 ? 0.0 : 1.0}}));
  r.on_planning_status("a", status({{"round", double(t / 2)}, {"planning_time_s", 0.01 * t}, {"views_remaining", 5}}));
  if (t % 5 == 0) r.on_completeness({double(t), 0.02 * t, 0.03 * t, {{"a", 0.01 * t}, {"b", 0.015 * t}}});
}

class RecordCheckpoint : public ::testing::Test {
 protected:
  std::string path_ = (std::filesystem::path(::testing::TempDir()) / "station_checkpoint_test.pb").string();
  void TearDown() override { std::filesystem::remove(path_); }
};

TEST_F(RecordCheckpoint, AResumedRecorderGoesOnAsIfTheStationHadOnlyMissedItsDowntime) {
  const auto t = team();
  // Counters the services had counted before the mission: the record counts from the start.
  auto before_start = [](TeamRecorder& r) {
    r.on_status("a", "sim", status({{"odometry_m", 50.0}, {"collisions", 1.0}}));
    r.on_status("b", "hlmap", status({{"gaps_detected", 3.0}}));
  };
  TeamRecorder uninterrupted(t), crashed(t), restarted(t);
  for (TeamRecorder* r : {&uninterrupted, &crashed}) {
    before_start(*r);
    r->start(100.0);
    for (int s = 0; s <= 10; ++s) hear_second(*r, s);
  }
  save_checkpoint(crashed.checkpoint(), path_);
  // The station is down from 110 to 113 s; the uninterrupted one heard those seconds too.
  for (int s = 11; s <= 13; ++s) hear_second(uninterrupted, s);
  const auto loaded = load_checkpoint(path_);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(checkpoint_mismatch(*loaded, t), "");
  restarted.on_pose("a", 114.0, pose_at(14.0, 0.0));  // the first pose the new station hears
  restarted.resume(*loaded, 114.0);
  for (TeamRecorder* r : {&uninterrupted, &restarted})
    for (int s = 14; s <= 20; ++s) hear_second(*r, s);

  const ExperimentRecord& want = uninterrupted.record();
  const ExperimentRecord& got = restarted.record();
  EXPECT_DOUBLE_EQ(restarted.mission_time_s(), 20.0);
  EXPECT_EQ(got.station_restarts, 1u);
  EXPECT_DOUBLE_EQ(got.station_unrecorded_s, 4.0);  // 110 s (the checkpoint) to 114 s (resumed)
  ASSERT_EQ(got.completeness.size(), want.completeness.size());  // samples of 0-20 s, 10 s kept
  for (size_t i = 0; i < got.completeness.size(); ++i) {
    EXPECT_DOUBLE_EQ(got.completeness[i].team, want.completeness[i].team);
    EXPECT_EQ(got.completeness[i].per_robot, want.completeness[i].per_robot);
  }
  for (const std::string id : {"a", "b"}) {
    const RobotTrack& w = want.robots.at(id);
    const RobotTrack& g = got.robots.at(id);
    // Counters since the start, carried over: odometry 50 -> 70 m, one collision in the mission.
    EXPECT_EQ(g.counters, w.counters) << id;
    EXPECT_DOUBLE_EQ(g.length_m, w.length_m) << id;
    EXPECT_EQ(g.collisions, w.collisions) << id;
    EXPECT_EQ(g.own_increment_seq, w.own_increment_seq) << id;
    // The downtime's samples are missing, nothing else.
    ASSERT_FALSE(g.times_s.empty());
    EXPECT_DOUBLE_EQ(g.times_s.front(), 0.0);
    EXPECT_DOUBLE_EQ(g.times_s.back(), w.times_s.back());
    EXPECT_EQ(g.times_s.size(), g.positions_m.size());
    EXPECT_EQ(g.orientations.size(), g.positions_m.size());
  }
  // b's map was out of sync with a's from 3 s on: the uninterrupted station heard it end at
  // 13 s, the restarted one at 14 s, its first status.
  EXPECT_EQ(want.robots.at("b").unsynced.at("a"), (std::vector<std::pair<double, double>>{{3.0, 13.0}}));
  EXPECT_EQ(got.robots.at("b").unsynced.at("a"), (std::vector<std::pair<double, double>>{{3.0, 14.0}}));
  EXPECT_DOUBLE_EQ(got.robots.at("a").length_m, 20.0);
  EXPECT_EQ(got.robots.at("a").collisions, 2u);
  EXPECT_DOUBLE_EQ(got.robots.at("b").counter("hlmap.gaps_detected"), 4.0);
  // Traffic and planning rounds: what both heard, less what only the uninterrupted one did.
  EXPECT_EQ(got.team_messages.at("a").at("incremental_map") + 3, want.team_messages.at("a").at("incremental_map"));
  EXPECT_EQ(got.team_bytes.at("b").at("exploration_route") + 3 * 30, want.team_bytes.at("b").at("exploration_route"));
  // Rounds 0-5 before, 7-10 after (round 6 was reported only in the downtime); none twice.
  EXPECT_EQ(got.planning_times_s.at("a").size(), 10u);
  EXPECT_EQ(want.planning_times_s.at("a").size(), 11u);
  // The summary says the station restarted.
  EXPECT_NE(summary_json(got).find("\"station\": {\"restarts\": 1, \"unrecorded_s\": 4"), std::string::npos);
}

TEST_F(RecordCheckpoint, ARestartCountsOnTopOfEarlierOnes) {
  const auto t = team();
  TeamRecorder first(t), second(t);
  first.start(0.0);
  first.on_pose("a", 10.0, pose_at(0, 0));
  second.resume(first.checkpoint(), 12.0);
  TeamRecorder third(t);
  third.resume(second.checkpoint(), 20.0);
  EXPECT_EQ(third.record().station_restarts, 2u);
  EXPECT_DOUBLE_EQ(third.record().station_unrecorded_s, 2.0 + 8.0);
}

TEST_F(RecordCheckpoint, NoFileIsNoCheckpoint) { EXPECT_FALSE(load_checkpoint(path_)); }

TEST_F(RecordCheckpoint, ABrokenFileIsAnErrorThatSaysWhichAndWhy) {
  {
    std::ofstream out(path_, std::ios::binary);
    out << "\xff\xff\xff\xff not a checkpoint";
  }
  try {
    load_checkpoint(path_);
    FAIL() << "a broken checkpoint was read";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find(path_), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("parse failed"), std::string::npos) << e.what();
  }
}

TEST_F(RecordCheckpoint, AnotherFormatIsNotRead) {
  const auto t = team();
  TeamRecorder r(t);
  v1::StationCheckpoint c = r.checkpoint();
  c.set_format(c.format() + 1);
  save_checkpoint(c, path_);
  EXPECT_THROW(load_checkpoint(path_), CheckpointError);
}

TEST_F(RecordCheckpoint, AnotherTeamsRecordIsNotResumed) {
  const auto t = team();
  TeamRecorder r(t);
  const v1::StationCheckpoint c = r.checkpoint();
  EXPECT_EQ(checkpoint_mismatch(c, t), "");
  EXPECT_EQ(checkpoint_mismatch(c, team("[{id: a, species: SLUGCAT}, {id: c, species: MR1000}]")),
            "it records robots a, b, the team has a, c");
  auto other_seed = team();
  other_seed.params.seed += 1;
  EXPECT_NE(checkpoint_mismatch(c, other_seed).find("seed"), std::string::npos);
  auto other_scene = team();
  other_scene.scene = "office";
  EXPECT_NE(checkpoint_mismatch(c, other_scene).find("scene"), std::string::npos);
}

TEST_F(RecordCheckpoint, ASaveIntoAMissingFolderFails) {
  const auto t = team();
  TeamRecorder r(t);
  EXPECT_THROW(save_checkpoint(r.checkpoint(), "/nonexistent-folder/station_checkpoint.pb"), CheckpointError);
}

}  // namespace
}  // namespace hexplore::evaluation
