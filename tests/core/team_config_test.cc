#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/core/config_error.h"
#include "common/core/liveness.h"
#include "common/core/team_config.h"

namespace hexplore::core {
namespace {

constexpr const char* kMinimal = R"(
species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - {id: a, species: SLUGCAT}
  - {id: b, species: MR1000, start: [1, 2, 0]}
)";

TEST(TeamConfig, LoadsDefaultTeamFile) {
  const auto c = load_team_config(std::string(HEXPLORE_SOURCE_DIR) + "/deploy/teams/default.yaml");
  ASSERT_EQ(c.robots.size(), 2u);
  EXPECT_EQ(c.scene, "single-building");
  EXPECT_NE(c.find_species("SLUGCAT"), nullptr);
  EXPECT_DOUBLE_EQ(c.params.eta_s_m, 1.0);  // paper default
}

TEST(TeamConfig, BuiltinLidarsMatchThePaper) {
  const auto slugcat = builtin_slugcat();
  ASSERT_EQ(slugcat.lidars.size(), 1u);
  EXPECT_EQ(slugcat.lidars[0].lines, 120);
  EXPECT_EQ(slugcat.lidars[0].rays_per_frame(), 216000);
  const auto mr = builtin_mr1000();
  ASSERT_EQ(mr.lidars.size(), 2u);
  EXPECT_TRUE(mr.lidars[0].gimbal);
  EXPECT_EQ(mr.lidars[1].lines, 80);
}

TEST(TeamConfig, ObservationLevelsRankByRange) {
  const auto c = parse_team_config(kMinimal, "test");
  EXPECT_EQ(c.observation_level(*c.find_species("SLUGCAT")), 1);
  EXPECT_EQ(c.observation_level(*c.find_species("MR1000")), 2);
}

// The legged third built-in: loads by name, mid-range 360 deg LiDAR, and terrain limits between
// the wheeled and the tracked species' in every respect, so that traversal levels can rank the
// three (MR1000 1 < QUADRUPED 2 < SLUGCAT).
TEST(TeamConfig, QuadrupedIsABuiltinBetweenTheOtherTwo) {
  const auto c = parse_team_config("species: [{builtin: QUADRUPED}]\nrobots: [{id: q, species: QUADRUPED}]\n", "test");
  const auto* q = c.find_species("QUADRUPED");
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(q->traversal_level, 2);
  EXPECT_DOUBLE_EQ(q->speed_mps, 0.6);
  EXPECT_DOUBLE_EQ(q->observation_range_m, 20.0);
  ASSERT_EQ(q->lidars.size(), 1u);
  EXPECT_EQ(q->lidars[0].lines, 32);
  EXPECT_DOUBLE_EQ(q->lidars[0].horizontal_max_deg - q->lidars[0].horizontal_min_deg, 360.0);
  const auto mr = builtin_mr1000(), slug = builtin_slugcat();
  EXPECT_GT(q->max_slope_deg, mr.max_slope_deg);
  EXPECT_LT(q->max_slope_deg, slug.max_slope_deg);
  EXPECT_GT(q->max_step_m, mr.max_step_m);
  EXPECT_LT(q->max_step_m, slug.max_step_m);
  EXPECT_GT(q->max_roughness_m, mr.max_roughness_m);
  EXPECT_LT(q->max_roughness_m, slug.max_roughness_m);
  EXPECT_GT(q->max_sparsity, mr.max_sparsity);
  EXPECT_LT(q->max_sparsity, slug.max_sparsity);
  EXPECT_LT(q->min_clearance_m, mr.min_clearance_m);
  EXPECT_GT(q->min_clearance_m, slug.min_clearance_m);
  EXPECT_EQ(builtin_species_names().size(), 3u);
  for (const auto& name : builtin_species_names()) EXPECT_EQ(builtin_species(name)->name, name);
  EXPECT_FALSE(builtin_species("WALKER"));
}

// Three species: observation levels rank the three ranges, and the SLUGCAT is raised above the
// quadruped's traversal level as the campus team files do.
TEST(TeamConfig, ThreeSpeciesRankByRangeAndByLevel) {
  const auto c = parse_team_config(
      "species:\n  - {builtin: SLUGCAT, traversal_level: 3}\n  - builtin: QUADRUPED\n  - builtin: MR1000\n"
      "robots: [{id: a, species: SLUGCAT}, {id: b, species: QUADRUPED}, {id: c, species: MR1000}]\n",
      "test");
  EXPECT_EQ(c.observation_level(*c.find_species("SLUGCAT")), 1);
  EXPECT_EQ(c.observation_level(*c.find_species("QUADRUPED")), 2);
  EXPECT_EQ(c.observation_level(*c.find_species("MR1000")), 3);
  EXPECT_EQ(c.find_species("SLUGCAT")->traversal_level, 3);
  EXPECT_EQ(c.find_species("QUADRUPED")->traversal_level, 2);
  EXPECT_EQ(c.find_species("MR1000")->traversal_level, 1);
}

// Both campus team files load and validate: 8 and 16 robots of the three species.
TEST(TeamConfig, CampusTeamFilesLoad) {
  for (const auto& [file, robots] : {std::pair<std::string, size_t>{"campus-8.yaml", 8}, {"campus-16.yaml", 16}}) {
    const auto c = load_team_config(std::string(HEXPLORE_SOURCE_DIR) + "/deploy/teams/" + file);
    EXPECT_EQ(c.scene, "campus") << file;
    EXPECT_EQ(c.robots.size(), robots) << file;
    ASSERT_EQ(c.species.size(), 3u) << file;
    for (const auto& s : c.species) {
      size_t n = 0;
      for (const auto& r : c.robots) n += r.species == s.name;
      EXPECT_GE(n, 2u) << file << " " << s.name;
    }
  }
}

void expect_error(const std::string& yaml, const std::string& key, const std::string& problem_part, int line = -1) {
  try {
    parse_team_config(yaml, "team.yaml");
    FAIL() << "expected a ConfigError for " << key;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "team.yaml");
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(e.problem().find(problem_part), std::string::npos) << e.what();
    if (line >= 0) {
      EXPECT_EQ(e.line(), line) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find("team.yaml"), std::string::npos);
  }
}

// Found by tests/fuzz/fuzz_team_yaml: a YAML key that is itself a list ("? - a") escaped as a
// yaml-cpp conversion error and ended the process instead of naming the problem.
TEST(TeamConfig, AKeyThatIsAListIsAConfigError) {
  expect_error("species:\n  - builtin: SLUGCAT\n? - builtin: MR1000\n: 3\nrobots: []\n", "", "keys must be plain names", 3);
  expect_error("species:\n  - {? [a, b] : 1}\nrobots: []\n", "species[0]", "keys must be plain names");
}

TEST(TeamConfig, UnknownSpeciesIsNamed) {
  expect_error("species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: WALKER}]\n", "robots[0].species",
               "unknown species 'WALKER'");
}

TEST(TeamConfig, UnknownBuiltinSpeciesListsTheKnownOnes) {
  expect_error("species: [{builtin: WALKER}]\nrobots: [{id: a, species: WALKER}]\n", "species[0].builtin",
               "known: SLUGCAT, MR1000, QUADRUPED");
}

// A requirement level sends every species of that level across: two species of one level
// must cross the same ground (SLUGCAT and QUADRUPED are both level 2 unless the file says).
TEST(TeamConfig, SpeciesOfOneLevelWithDifferentLimitsAreRejected) {
  expect_error("species: [{builtin: SLUGCAT}, {builtin: QUADRUPED}]\nrobots: [{id: a, species: SLUGCAT}]\n",
               "species[1].traversal_level", "share traversal level 2");
  EXPECT_NO_THROW(parse_team_config(
      "species: [{builtin: SLUGCAT}, {name: SLUG2, builtin: SLUGCAT, speed_mps: 0.3}]\n"
      "robots: [{id: a, species: SLUG2}]\n",
      "team.yaml"));
}

TEST(TeamConfig, TypoKeyIsRejectedWithLine) {
  expect_error("species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\nparams:\n  eta_x_m: 3\n",
               "params.eta_x_m", "unknown key", 4);
}

TEST(TeamConfig, WrongTypeIsRejected) {
  expect_error("species: [{builtin: SLUGCAT, speed_mps: fast}]\nrobots: [{id: a, species: SLUGCAT}]\n",
               "species[0].speed_mps", "cannot read 'fast' as a number");
}

TEST(TeamConfig, NanIsRejected) {
  expect_error("species: [{builtin: SLUGCAT, speed_mps: .nan}]\nrobots: [{id: a, species: SLUGCAT}]\n",
               "species[0].speed_mps", "finite");
}

TEST(TeamConfig, TaskViewChoiceIsReadAndChecked) {
  EXPECT_EQ(parse_team_config(kMinimal, "t").params.task_view_choice, "weakest_species");
  EXPECT_EQ(parse_team_config(std::string(kMinimal) + "params: {task_view_choice: best_score}\n", "t").params.task_view_choice,
            "best_score");
  expect_error(std::string(kMinimal) + "params: {task_view_choice: nearest}\n", "params.task_view_choice",
               "must be weakest_species or best_score, got 'nearest'");
}

TEST(TeamConfig, ClusterWorkIsReadAndChecked) {
  EXPECT_EQ(parse_team_config(kMinimal, "t").params.cluster_work, "cover");
  EXPECT_EQ(parse_team_config(std::string(kMinimal) + "params: {cluster_work: every_view}\n", "t").params.cluster_work,
            "every_view");
  expect_error(std::string(kMinimal) + "params: {cluster_work: all}\n", "params.cluster_work",
               "must be cover or every_view, got 'all'");
}

TEST(TeamConfig, PlannerSeedIsReadAndDefaultsToNone) {
  EXPECT_EQ(parse_team_config(kMinimal, "t").params.planner_seed, 0u);
  const auto p = parse_team_config(std::string(kMinimal) + "params: {seed: 5, planner_seed: 1000008}\n", "t").params;
  EXPECT_EQ(p.seed, 5u);
  EXPECT_EQ(p.planner_seed, 1000008u);
}

TEST(TeamConfig, DuplicateRobotIsRejected) {
  expect_error("species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}, {id: a, species: SLUGCAT}]\n",
               "robots[1].id", "duplicate robot id");
}

TEST(TeamConfig, SyntaxErrorHasLine) {
  expect_error("species: [\nrobots: {", "", "YAML syntax error");
}

TEST(TeamConfig, MissingFileIsNamed) {
  try {
    load_team_config("/nonexistent/team.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/team.yaml");
    EXPECT_NE(e.problem().find("cannot open"), std::string::npos);
  }
}

TEST(TeamConfig, ExplorationRegionIsReadAndChecked) {
  const std::string base = "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\n";
  EXPECT_FALSE(parse_team_config(base, "t").exploration_region.isEmpty());
  EXPECT_TRUE(parse_team_config(base, "t").exploration_region.contains(Eigen::Vector3d(1e9, -1e9, 0)));
  const auto c = parse_team_config(base + "exploration_region: {min: [0, 0, -1], max: [10, 20, 5]}\n", "t");
  EXPECT_TRUE(c.exploration_region.contains(Eigen::Vector3d(5, 5, 0)));
  EXPECT_FALSE(c.exploration_region.contains(Eigen::Vector3d(11, 5, 0)));
  try {
    parse_team_config(base + "exploration_region: {min: [0, 0, 0], max: [10, -1, 5]}\n", "t.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "exploration_region");
    EXPECT_NE(e.problem().find("max must exceed min"), std::string::npos);
  }
}

TEST(TeamConfig, SceneImportIsReadAndChecked) {
  const std::string base = "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\n";
  EXPECT_EQ(parse_team_config(base, "t").scene_import.up_axis, "z");
  const auto c = parse_team_config(
      base + "scene_import: {up_axis: y, scale: 0.001, yaw_deg: 90, translation: [1, 2, 3]}\n", "t");
  EXPECT_EQ(c.scene_import.up_axis, "y");
  EXPECT_DOUBLE_EQ(c.scene_import.scale, 0.001);
  EXPECT_DOUBLE_EQ(c.scene_import.yaw_deg, 90.0);
  EXPECT_EQ(c.scene_import.translation_m, Eigen::Vector3d(1, 2, 3));
  const std::pair<const char*, const char*> bad[] = {{"scene_import: {up_axis: x}", "scene_import.up_axis"},
                                                     {"scene_import: {scale: 0}", "scene_import.scale"},
                                                     {"scene_import: {yaw_deg: 400}", "scene_import.yaw_deg"},
                                                     {"scene_import: {shear: 1}", "scene_import.shear"}};
  for (const auto& [text, key] : bad) {
    try {
      parse_team_config(base + text + "\n", "t.yaml");
      ADD_FAILURE() << "accepted " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.key(), key) << text;
      EXPECT_EQ(e.line(), 3) << text;
    }
  }
}

TEST(TeamConfig, RadioModelIsReadAndChecked) {
  const std::string base = "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\n";
  EXPECT_FALSE(parse_team_config(base, "t").transport.radio.active());  // an ideal link by default
  const auto c = parse_team_config(base +
                                       "transport:\n"
                                       "  radio:\n"
                                       "    bandwidth_bytes_per_s: 4096\n"
                                       "    latency_s: 0.2\n"
                                       "    loss: 0.1\n"
                                       "    range_m: 25\n"
                                       "    max_queue_age_s: 3\n",
                                   "t");
  const RadioConfig& radio = c.transport.radio;
  EXPECT_TRUE(radio.active());
  EXPECT_DOUBLE_EQ(radio.bandwidth_bytes_per_s, 4096.0);
  EXPECT_DOUBLE_EQ(radio.latency_s, 0.2);
  EXPECT_DOUBLE_EQ(radio.loss, 0.1);
  EXPECT_DOUBLE_EQ(radio.range_m, 25.0);
  EXPECT_DOUBLE_EQ(radio.max_queue_age_s, 3.0);
  const std::pair<const char*, const char*> bad[] = {
      {"    bandwith_bytes_per_s: 4096", "transport.radio.bandwith_bytes_per_s"},  // typo: unknown key
      {"    bandwidth_bytes_per_s: -1", "transport.radio.bandwidth_bytes_per_s"},
      {"    latency_s: 90", "transport.radio.latency_s"},
      {"    loss: 1.0", "transport.radio.loss"},
      {"    loss: lots", "transport.radio.loss"},
      {"    range_m: -5", "transport.radio.range_m"},
      {"    max_queue_age_s: 0", "transport.radio.max_queue_age_s"}};
  for (const auto& [text, key] : bad) {
    try {
      parse_team_config(base + "transport:\n  radio:\n" + text + "\n", "t.yaml");
      ADD_FAILURE() << "accepted " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.file(), "t.yaml");
      EXPECT_EQ(e.key(), key) << text;
      EXPECT_EQ(e.line(), 5) << text;
    }
  }
}

TEST(TeamConfig, RadioOutagesAreReadAndChecked) {
  const std::string base = "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}, {id: b, species: SLUGCAT}]\n";
  const auto c = parse_team_config(base + "transport:\n  radio:\n    outages:\n      - {robot: b, from_s: 60, to_s: 120}\n", "t");
  ASSERT_EQ(c.transport.radio.outages.size(), 1u);
  EXPECT_EQ(c.transport.radio.outages[0].robot, "b");
  EXPECT_DOUBLE_EQ(c.transport.radio.outages[0].from_s, 60.0);
  EXPECT_DOUBLE_EQ(c.transport.radio.outages[0].to_s, 120.0);
  EXPECT_TRUE(c.transport.radio.active());
  const std::pair<const char*, const char*> bad[] = {
      {"      - {robot: c, from_s: 60, to_s: 120}", "transport.radio.outages[0].robot"},  // not in the team
      {"      - {robot: b, from_s: 60, to_s: 60}", "transport.radio.outages[0].to_s"},
      {"      - {robot: b, from_s: 60, to_s: 120, when: now}", "transport.radio.outages[0].when"},
      {"      - b", "transport.radio.outages[0]"}};
  for (const auto& [text, key] : bad) {
    try {
      parse_team_config(base + "transport:\n  radio:\n    outages:\n" + text + "\n", "t.yaml");
      ADD_FAILURE() << "accepted " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.key(), key) << text;
    }
  }
}

TEST(TeamConfig, LivenessTimeoutsAreReadAndChecked) {
  const std::string base = "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\n";
  const LivenessParams defaults = parse_team_config(base, "t").params.liveness;
  EXPECT_DOUBLE_EQ(defaults.planning_team_s, 5.0);
  EXPECT_DOUBLE_EQ(defaults.obstacle_s, 2.5);
  const auto c = parse_team_config(base + "params:\n  liveness:\n    planning_team_s: 7\n    sim_body_s: 1.5\n", "t");
  EXPECT_DOUBLE_EQ(c.params.liveness.planning_team_s, 7.0);
  EXPECT_DOUBLE_EQ(c.params.liveness.sim_body_s, 1.5);
  EXPECT_DOUBLE_EQ(c.params.liveness.station_s, defaults.station_s);  // unlisted keys keep their default
  const std::pair<const char*, const char*> bad[] = {{"    planning_team: 7", "params.liveness.planning_team"},
                                                     {"    obstacle_s: 0", "params.liveness.obstacle_s"},
                                                     {"    station_s: -3", "params.liveness.station_s"},
                                                     {"    body_filter_s: .inf", "params.liveness.body_filter_s"}};
  for (const auto& [text, key] : bad) {
    try {
      parse_team_config(base + "params:\n  liveness:\n" + text + "\n", "t.yaml");
      ADD_FAILURE() << "accepted " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.key(), key) << text;
      EXPECT_EQ(e.line(), 5) << text;
    }
  }
}

TEST(Liveness, ATeammateIsAliveWhileHeardWithinItsTimeout) {
  Liveness team(2.0);
  EXPECT_FALSE(team.alive("a", 0));  // never heard
  team.heard("a", 1'000'000'000);
  EXPECT_TRUE(team.alive("a", 3'000'000'000));   // exactly the time-out: still alive
  EXPECT_FALSE(team.alive("a", 3'000'000'001));  // then gone
  team.heard("a", 3'500'000'000);                // heard again: back
  EXPECT_TRUE(team.alive("a", 4'000'000'000));
  EXPECT_TRUE(team.fresh(2.0));
  EXPECT_FALSE(team.fresh(2.1));
  EXPECT_THROW(Liveness(0.0), std::invalid_argument);
  EXPECT_THROW(Liveness(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::core
