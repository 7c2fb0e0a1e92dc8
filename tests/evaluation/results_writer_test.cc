#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/evaluation/results_writer.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::evaluation {
namespace {

ExperimentRecord sample_record(uint64_t seed, double time_s, double final_completeness) {
  ExperimentRecord r;
  r.scene = "single-building";
  r.planner = "hexplore";
  r.mode = "processes";
  r.seed = seed;
  r.exploration_time_s = time_s;
  r.end_reason = "no task views remain";
  for (int i = 0; i <= 10; ++i) {
    CompletenessSample s;
    s.sim_time_s = time_s * i / 10.0;
    s.team = final_completeness * i / 10.0;
    s.team_observable = std::min(1.0, s.team * 1.1);
    s.per_robot = {{"a", s.team * 0.7}, {"b", s.team * 0.5}};
    r.completeness.push_back(s);
  }
  r.robots["a"].species = "SLUGCAT";
  r.robots["b"].species = "MR1000";
  for (int i = 0; i < 20; ++i) {
    r.robots["a"].positions_m.emplace_back(i * 0.5, 0.0, 0.0);
    r.robots["a"].times_s.push_back(i);
    r.robots["b"].positions_m.emplace_back(0.0, i * 0.5, 0.0);
    r.robots["b"].times_s.push_back(i);
  }
  r.robots["a"].length_m = 9.5;
  r.robots["a"].longest_blocked_s = 4.5;
  r.robots["b"].length_m = 9.5;
  r.team_bytes["a"]["pose"] = 2048;
  r.team_bytes["a"]["incremental_map"] = 10240;
  r.team_messages["a"]["pose"] = 100;
  r.team_messages["a"]["incremental_map"] = 100;
  // What the two other map strategies would have sent, and the map re-sync of robot b.
  r.robots["a"].counters = {{"hlmap.full_map_bytes", 409600.0}, {"mapping.raw_map_bytes", 4096000.0}};
  r.robots["b"].counters = {{"hlmap.full_map_bytes", 204800.0}, {"mapping.raw_map_bytes", 2048000.0},
                            {"hlmap.gaps_detected", 3}, {"hlmap.gaps_repaired", 2},
                            {"hlmap.radio_out_of_range", 40}, {"sim.radio_out_of_range", 5}};
  // b applied a's increments up to 7 of 9; a never reported how far it applied b's.
  r.robots["a"].own_increment_seq = 9;
  r.robots["b"].own_increment_seq = 4;
  r.robots["b"].synced_seq = {{"a", 7}};
  r.robots["b"].unsynced = {{"a", {{10.0, 12.0}, {50.0, -1.0}}}};  // out of sync from 50 s to the end
  r.planning_times_s["a"] = {0.05, 0.07};
  r.final_map_points_m = {{0, 0, 0}, {5, 5, 3}, {9, 1, 1}};
  // An earlier periodic report of "a" (left out of the summary's counts), then the final ones.
  r.open_targets = {{50, "a", 5, {4, 4, 1}, true, 10, 0, "no_normal", "occluded", 0},
                    {100, "a", 7, {1, 2, 3}, true, 40, 30, "density", "has_view", 1},
                    {100, "a", 9, {2, 2, 0}, false, 20, 5, "angle", "given_up", 2},
                    {100.5, "b", 7, {1, 2, 3}, true, 40, 30, "density", "has_view", 0}};
  return r;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ResultsWriter, WritesEveryFile) {
  const hexplore::testing::ScratchDir scratch("results_writer_test");
  const auto dir = scratch.path() / "results";
  const auto files = write_results(sample_record(1, 100.0, 0.8), dir.string());
  EXPECT_EQ(files.size(), 12u);  // seven tables, a TUM trajectory per robot, the map as PLY, PCD, OctoMap
  for (const auto& f : files) EXPECT_GT(std::filesystem::file_size(f), 20u) << f;
  const auto summary = slurp(dir / "summary.json");
  EXPECT_NE(summary.find("\"final_completeness\": 0.8"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"accumulated_completeness\": 0.96"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"end_reason\": \"no task views remain\""), std::string::npos);
  EXPECT_NE(summary.find("\"collisions\": 0, \"longest_blocked_s\": 4.5"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"a\": {\"total\": 2, \"by_state\": {\"given_up\": 1, \"has_view\": 1}, "
                         "\"by_gap\": {\"angle\": 1, \"density\": 1}}"),
            std::string::npos)
      << summary;
  const auto open = slurp(dir / "open_targets.csv");
  EXPECT_NE(open.find("100,a,9,2,2,0,0,20,5,angle,given_up,2"), std::string::npos) << open;
  EXPECT_NE(open.find("50,a,5,4,4,1,1,10,0,no_normal,occluded,0"), std::string::npos) << "every report is listed";
  const auto comm = slurp(dir / "communication.csv");
  EXPECT_NE(comm.find("robot,category,messages,cumulative_kb,average_kb_per_s\n"), std::string::npos) << comm;
  EXPECT_NE(comm.find("a,incremental_map,100,10,0.1"), std::string::npos) << comm;
  EXPECT_NE(comm.find("b,pose,0,0,0"), std::string::npos) << comm;
  // Table 4-5: per robot (summed, divided by two robots), over 100 s.
  const auto strategies = slurp(dir / "map_transmission.csv");
  EXPECT_NE(strategies.find("incremental_high_level,5,0.05\n"), std::string::npos) << strategies;
  EXPECT_NE(strategies.find("full_high_level,300,3\n"), std::string::npos) << strategies;
  EXPECT_NE(strategies.find("full_perception,3000,30\n"), std::string::npos) << strategies;
  EXPECT_NE(summary.find("\"saving_vs_full_high_level\": 0.9833333333"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"map_sync\": {\"gaps_detected\": 3, \"gaps_repaired\": 2"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"increments_behind\": {\"a\": 2}, \"out_of_sync\": {\"a\": {\"stretches\": 2, "
                         "\"longest_s\": 50, \"last_resynced_s\": null, \"open_at_end\": true}}}"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("\"increments_behind\": {\"b\": null}, \"out_of_sync\": {}}"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"station\": {\"restarts\": 0, \"unrecorded_s\": 0}"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"radio_drops\": {\"expired\": 0, \"lost\": 0, \"out_of_range\": 45}"), std::string::npos)
      << summary;
  // TUM: "time x y z qx qy qz qw", one line per sample (no orientation recorded: identity).
  const auto tum = slurp(dir / "trajectory_b.tum");
  EXPECT_EQ(std::count(tum.begin(), tum.end(), '\n'), 20);
  EXPECT_NE(tum.find("\n2 0 1 0 0 0 0 1\n"), std::string::npos) << tum;
  const auto completeness = slurp(dir / "completeness.csv");
  EXPECT_EQ(std::count(completeness.begin(), completeness.end(), '\n'), 12);
}

// A run under another planner stream says so: its seed alone would not reproduce it.
TEST(ResultsWriter, SummaryNamesThePlannerSeed) {
  ExperimentRecord r = sample_record(5, 100.0, 0.8);
  EXPECT_NE(summary_json(r).find("\"planner_seed\": 0,"), std::string::npos);
  r.planner_seed = 1000008;
  EXPECT_NE(summary_json(r).find("\"seed\": 5,\n  \"planner_seed\": 1000008,"), std::string::npos);
}

TEST(ResultsWriter, MultiRunSummaryHasMeanAndSpread) {
  const auto json = multi_run_summary_json({sample_record(1, 100.0, 0.8), sample_record(2, 200.0, 0.6)});
  EXPECT_NE(json.find("\"exploration_time_s\": {\"mean\": 150, \"stddev\": 70.71067812, \"min\": 100, \"max\": 200}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"seeds\": [1, 2]"), std::string::npos);
  EXPECT_NE(json.find("\"final_observable_completeness\": {"), std::string::npos);
  EXPECT_NE(json.find("\"end_reasons\": ["), std::string::npos);
  // Per robot and category, and the three map strategies (seed 1: 2 KB of pose over 100 s, 2 robots).
  EXPECT_NE(json.find("\"pose\": {\"mean\": 0.0075"), std::string::npos) << json;
  EXPECT_NE(json.find("\"map_transmission_kb_per_s\": {"), std::string::npos) << json;
  EXPECT_NE(json.find("\"map_gaps_detected\": {\"mean\": 3"), std::string::npos) << json;
  EXPECT_NE(json.find("\"longest_blocked_s\": {\"mean\": 4.5"), std::string::npos) << json;
}

TEST(ExperimentRecord, AReportAtTheSameTimeReplacesTheEarlierOneInsteadOfDoublingIt) {
  // In lockstep the final request can be answered at the time of a periodic one: before, the
  // summary then counted every open target twice.
  ExperimentRecord r;
  OpenTargetRow row;
  row.state = "has_view";
  row.key = 1;
  r.add_open_targets_report("a", 60.0, {row});
  row.key = 2;
  r.add_open_targets_report("a", 600.0, {row});
  r.add_open_targets_report("b", 600.0, {row});
  row.key = 3;
  r.add_open_targets_report("a", 600.0, {row});  // the same time again: replaces a's 600 s report
  EXPECT_EQ(r.open_targets.size(), 3u);
  const auto latest = r.latest_open_targets();
  ASSERT_EQ(latest.size(), 2u);
  for (const auto& t : latest) {
    EXPECT_EQ(t.sim_time_s, 600.0);
    EXPECT_EQ(t.key, t.robot == "a" ? 3u : 2u);
  }
}

TEST(ResultsWriter, UnwritableFolderIsNamed) {
  EXPECT_THROW(write_results(sample_record(1, 10.0, 0.5), "/proc/hexplore-cannot-write"), std::runtime_error);
}

}  // namespace
}  // namespace hexplore::evaluation
