#include "common/sim/scenes.h"

#include <array>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/sim/building.h"
#include "common/sim/mesh_builder.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"
#include "common/sim/robot_motion.h"
#include "common/sim/scene_error.h"

namespace hexplore::sim {
namespace {

TEST(Scenes, GenerationIsDeterministicPerSeed) {
  for (const auto& name : scene_names()) {
    const auto a = generate_scene(name, 7), b = generate_scene(name, 7), c = generate_scene(name, 8);
    EXPECT_EQ(a.mesh.content_hash(), b.mesh.content_hash()) << name;
    EXPECT_NE(a.mesh.content_hash(), c.mesh.content_hash()) << name;
    EXPECT_GT(a.mesh.triangle_count(), 1000u) << name;
    EXPECT_LT(a.mesh.triangle_count(), 50000u) << name;  // moderate, so scans stay fast
  }
}

TEST(Scenes, DoorsTooSmallForTheRobotsAreRejected) {
  MeshBuilder b;
  BuildingSpec spec;
  spec.footprint = {0, 0, 10, 10};
  spec.doors = {{Side::kSouth, 2.0, 1.0, 2.2}};
  EXPECT_THROW(add_building(b, spec), SceneError);
  spec.doors = {{Side::kSouth, 2.0, kMinDoorWidthM, kMinDoorHeightM}};
  EXPECT_NO_THROW(add_building(b, spec));
  // Robots fit: both species are narrower and lower than the smallest door.
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    EXPECT_LT(2 * species.body_half_extents_m.y() + 0.3, kMinDoorWidthM) << species.name;
    EXPECT_LT(species.min_clearance_m, kMinDoorHeightM) << species.name;
  }
}

TEST(Scenes, UnknownNameListsTheKnownOnes) {
  try {
    generate_scene("no-such-scene", 1);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("single-building"), std::string::npos);
  }
  EXPECT_THROW(load_scene("/nonexistent/scene.ply", 1), SceneError);
}

TEST(Scenes, MeshPathsResolveBesideTheTeamFile) {
  EXPECT_EQ(resolve_scene("single-building", "/a/team.yaml"), "single-building");
  const std::string shared = std::string(HEXPLORE_SHARED_DIR) + "/scenes/collapsed_town_osrf/";
  if (std::filesystem::exists(shared + "collapsed_town.ply"))
    EXPECT_EQ(resolve_scene("collapsed_town.ply", shared + "team.yaml"), shared + "collapsed_town.ply");
  EXPECT_EQ(resolve_scene("missing.ply", "/nowhere/team.yaml"), "missing.ply");  // load_scene then names it
}

TEST(Scenes, SizesMatchThePaper) {
  const auto single = generate_scene("single-building", 1);
  const auto b = single.mesh.bounds();
  EXPECT_GE(b.max().z(), 12.0);  // tall main building
  const auto multi_scene = generate_scene("multi-building", 1);
  const Eigen::Vector3d multi = multi_scene.site.sizes();
  EXPECT_NEAR(multi.x() * multi.y(), 1554.0, 30.0);
}

// Every suggested start (the default team's (2,-3) and (4,-3) among them) is flat, free
// ground where both species can stand and drive a metre.
TEST(Scenes, SuggestedStartsAreFreeFlatGround) {
  for (const auto& name : scene_names()) {
    const auto scene = generate_scene(name, 1);
    const RayCaster caster(scene.mesh);
    for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()})
      for (const auto& s : scene.suggested_starts) {
        RobotMotion robot(caster, species, s, M_PI / 2);
        EXPECT_NEAR(robot.ground_position().z(), 0.0, 1e-3) << name;
        robot.follow({s + Eigen::Vector3d(0, 1.0, 0)});
        for (int i = 0; i < 100 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1);
        EXPECT_EQ(robot.state(), MotionState::kIdle) << name << " " << species.name << " at " << s.transpose() << ": "
                                                     << to_string(robot.block_reason());
      }
  }
}

// single-building needs both species: only the tracked robot reaches the annex's indoor space
// (across the debris yard) and the first floor (up the stairs) from the default starts.
TEST(Scenes, SingleBuildingAnnexAndUpperFloorNeedTheTrackedRobot) {
  const auto scene = generate_scene("single-building", 1);
  const RayCaster caster(scene.mesh);
  auto count = [&](const core::SpeciesConfig& species, const Eigen::Vector3d& start) {
    const std::vector<Eigen::Vector3d> starts = {start};
    size_t annex = 0, upstairs = 0, total = 0;
    for (const auto& p : reachable_ground(caster, species, starts, scene.site)) {
      ++total;
      annex += p.x() > 23.8 && p.x() < 31.2 && p.y() > 2.3 && p.y() < 13.7;
      upstairs += p.z() > 3.0;
    }
    return std::array<size_t, 3>{annex, upstairs, total};
  };
  const auto tracked = count(core::builtin_slugcat(), {2, -3, 0});
  const auto wheeled = count(core::builtin_mr1000(), {4, -3, 0});
  EXPECT_GT(tracked[0], 100u);
  EXPECT_GT(tracked[1], 300u);
  EXPECT_EQ(wheeled[0], 0u);
  EXPECT_EQ(wheeled[1], 0u);
  EXPECT_GT(wheeled[2], 2000u);  // but it does get around the outside and into the main building
}

// The OSRF collapsed town (third-party COLLADA-derived geometry): loads, and a robot of
// each species is placed in a street and driven along it.
TEST(Scenes, OsrfCollapsedTownLoadsAndRobotsDrive) {
  const std::string path = std::string(HEXPLORE_SHARED_DIR) + "/scenes/collapsed_town_osrf/collapsed_town.ply";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared scene not found at " << path;
  const auto scene = load_scene(path, 1);
  EXPECT_EQ(scene.mesh.triangle_count(), 15036u);
  const RayCaster caster(scene.mesh);
  // The street between the four buildings (x = 0 separates west and east blocks).
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    RobotMotion robot(caster, species, {0.0, -25.0, 0.0}, M_PI / 2);
    robot.follow({{0.0, -20.0, 0.0}, {0.0, -15.0, 0.0}});
    for (int i = 0; i < 600 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1);
    EXPECT_EQ(robot.state(), MotionState::kIdle) << species.name << ": " << to_string(robot.block_reason());
    EXPECT_NEAR(robot.odometry_m(), 10.0, 0.05) << species.name;
  }
}

// A team file's scene_import places a mesh scene the same way for the sim and the evaluator.
TEST(Scenes, TeamSceneAppliesTheTeamFilesImportOptions) {
  MeshBuilder b;
  b.box({0, 0, 0}, {2, 1, 3});  // 2 x 1 x 3, written Y-up below
  const std::string dir = ::testing::TempDir() + "/team_scene_" + std::to_string(getpid());
  std::filesystem::create_directories(dir);
  write_mesh(b.take(), dir + "/box.ply");
  const std::string yaml = "scene: box.ply\nscene_import: {up_axis: y, scale: 2, translation: [10, 0, 0]}\n"
                           "species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}]\n";
  std::ofstream(dir + "/team.yaml") << yaml;
  const auto scene = load_team_scene(core::load_team_config(dir + "/team.yaml"));
  // (x, y, z) <- (x, -z, y), then x2, then +10 in x.
  const Eigen::AlignedBox3f box = scene.mesh.bounds();
  EXPECT_NEAR(box.min().x(), 10.0f, 1e-4f);
  EXPECT_NEAR(box.max().x(), 14.0f, 1e-4f);
  EXPECT_NEAR(box.min().y(), -6.0f, 1e-4f);
  EXPECT_NEAR(box.max().y(), 0.0f, 1e-4f);
  EXPECT_NEAR(box.max().z(), 2.0f, 1e-4f);
}

// The original COLLADA file (inches, Z_UP; assimp applies the unit and turns it Y-up) loads
// with up_axis = kY and the model's scale into the same geometry as the converted PLY part.
TEST(Scenes, OsrfColladaOriginalLoadsWithImportOptions) {
  const std::string dir = std::string(HEXPLORE_SHARED_DIR) + "/scenes/collapsed_town_osrf/";
  if (!std::filesystem::exists(dir + "source/collapsed_house.dae")) GTEST_SKIP() << "shared scene not found";
  MeshImportOptions options;
  options.up_axis = UpAxis::kY;
  options.scale = 1.5;
  const auto dae = load_mesh(dir + "source/collapsed_house.dae", options).bounds();
  const auto ply = load_mesh(dir + "parts/collapsed_house.ply").bounds();
  EXPECT_LT((dae.min() - ply.min()).norm(), 0.02);
  EXPECT_LT((dae.max() - ply.max()).norm(), 0.02);
}

}  // namespace
}  // namespace hexplore::sim
