#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/station/results_writer.h"

namespace hexplore::station {
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
  r.planning_times_s["a"] = {0.05, 0.07};
  r.final_map_points_m = {{0, 0, 0}, {5, 5, 3}, {9, 1, 1}};
  r.open_targets = {{"a", 7, {1, 2, 3}, true, 40, 30, "density", "has_view", 1},
                    {"a", 9, {2, 2, 0}, false, 20, 5, "angle", "given_up", 2},
                    {"b", 7, {1, 2, 3}, true, 40, 30, "density", "has_view", 0}};
  return r;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ResultsWriter, WritesEveryFile) {
  const auto dir = std::filesystem::temp_directory_path() / "hexplore_results_test";
  std::filesystem::remove_all(dir);
  const auto files = write_results(sample_record(1, 100.0, 0.8), dir.string());
  EXPECT_EQ(files.size(), 8u);
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
  EXPECT_NE(open.find("a,9,2,2,0,0,20,5,angle,given_up,2"), std::string::npos) << open;
  const auto comm = slurp(dir / "communication.csv");
  EXPECT_NE(comm.find("a,incremental_map,10,0.1"), std::string::npos) << comm;
  const auto completeness = slurp(dir / "completeness.csv");
  EXPECT_EQ(std::count(completeness.begin(), completeness.end(), '\n'), 12);
}

TEST(ResultsWriter, MultiRunSummaryHasMeanAndSpread) {
  const auto json = multi_run_summary_json({sample_record(1, 100.0, 0.8), sample_record(2, 200.0, 0.6)});
  EXPECT_NE(json.find("\"exploration_time_s\": {\"mean\": 150, \"stddev\": 70.71067812, \"min\": 100, \"max\": 200}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"seeds\": [1, 2]"), std::string::npos);
  EXPECT_NE(json.find("\"final_observable_completeness\": {"), std::string::npos);
  EXPECT_NE(json.find("\"end_reasons\": ["), std::string::npos);
  EXPECT_NE(json.find("\"longest_blocked_s\": {\"mean\": 4.5"), std::string::npos) << json;
}

TEST(ResultsWriter, UnwritableFolderIsNamed) {
  EXPECT_THROW(write_results(sample_record(1, 10.0, 0.5), "/proc/hexplore-cannot-write"), std::runtime_error);
}

}  // namespace
}  // namespace hexplore::station
