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
#include "common/sim/scene_parts.h"
#include "tests/support/scratch_dir.h"

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
  // Robots fit: every built-in species is narrower and lower than the smallest door.
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000(), core::builtin_quadruped()}) {
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
  if (std::filesystem::exists(shared + "collapsed_town.ply")) {
    EXPECT_EQ(resolve_scene("collapsed_town.ply", shared + "team.yaml"), shared + "collapsed_town.ply");
  }
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
// ground where every built-in species can stand and drive a metre.
TEST(Scenes, SuggestedStartsAreFreeFlatGround) {
  for (const auto& name : scene_names()) {
    const auto scene = generate_scene(name, 1);
    const RayCaster caster(scene.mesh);
    for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000(), core::builtin_quadruped()})
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

// small-building keeps that character: the annex behind the debris yard is the tracked
// robot's, and there is ground to stand on 7 m and more from every facade of the 7 m building
// (seen within 45 deg up to its top).
TEST(Scenes, SmallBuildingAnnexNeedsTheTrackedRobotAndEveryFacadeHasRoomInFront) {
  const auto scene = generate_scene("small-building", 1);
  const RayCaster caster(scene.mesh);
  auto annex_cells = [&](const core::SpeciesConfig& species, const Eigen::Vector3d& start) {
    size_t annex = 0, total = 0;
    std::array<bool, 4> stand_off{};  // west, east, south, north of the main building
    const Eigen::AlignedBox3d everywhere(Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(30, 30, 10));
    const std::vector<Eigen::Vector3d> starts = {start};
    for (const auto& p : reachable_ground(caster, species, starts, everywhere)) {
      ++total;
      annex += p.x() > 13.8 && p.x() < 18.2 && p.y() > 3.3 && p.y() < 8.7;
      const bool beside_x = p.y() > 3 && p.y() < 11;
      const bool beside_y = p.x() > 3 && p.x() < 11;
      stand_off[0] = stand_off[0] || (beside_x && p.x() < 3 - 7.0);
      stand_off[1] = stand_off[1] || (beside_x && p.x() > 18.5 + 7.0);
      stand_off[2] = stand_off[2] || (beside_y && p.y() < 3 - 7.0);
      stand_off[3] = stand_off[3] || (beside_y && p.y() > 11 + 7.0);
    }
    return std::make_tuple(annex, total, stand_off);
  };
  const auto [tracked_annex, tracked_total, tracked_room] = annex_cells(core::builtin_slugcat(), {2, -3, 0});
  const auto [wheeled_annex, wheeled_total, wheeled_room] = annex_cells(core::builtin_mr1000(), {4, -3, 0});
  EXPECT_GT(tracked_annex, 50u);
  EXPECT_EQ(wheeled_annex, 0u);
  for (int side = 0; side < 4; ++side) EXPECT_TRUE(wheeled_room[size_t(side)]) << "side " << side;
  EXPECT_GT(wheeled_total, 2000u);
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
  const hexplore::testing::ScratchDir scratch("team_scene");
  const std::string dir = scratch.path().string();
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


// office: every room's door is a real gap of 0.90-1.00 m in its corridor wall (wider than the
// wheeled body by at least 0.2 m, narrower than it is long) and the walls either side of it
// are solid; rooms are small.
TEST(Scenes, OfficeDoorsAreGapsJustWiderThanTheWheeledBody) {
  const auto layout = detail::office_layout(1);
  const auto scene = generate_scene("office", 1);
  const RayCaster caster(scene.mesh);
  const double mr1000_width = 2 * core::builtin_mr1000().body_half_extents_m.y();
  ASSERT_GE(layout.rooms.size(), 30u);
  for (const auto& room : layout.rooms) {
    const Rect& d = room.door;
    EXPECT_GE(room.door_width_m, 0.90);
    EXPECT_LE(room.door_width_m, 1.00);
    EXPECT_GE(room.door_width_m, mr1000_width + 0.2);
    EXPECT_NEAR(d.x1 - d.x0, room.door_width_m, 1e-9);
    const double w = room.interior.x1 - room.interior.x0, depth = room.interior.y1 - room.interior.y0;
    EXPECT_GE(w, 2.2);
    EXPECT_LE(w, 4.6);
    EXPECT_LE(depth, 3.8);
    // Across the wall line, at 1 m: open through the door, wall just beside it.
    const double y_from = room.door_faces_north ? d.y0 - 0.5 : d.y1 + 0.5;
    const Eigen::Vector3f dir(0, room.door_faces_north ? 1.0f : -1.0f, 0);
    const double mid = 0.5 * (d.x0 + d.x1);
    for (double x : {mid, d.x0 + 0.05, d.x1 - 0.05})
      EXPECT_EQ(caster.cast(Eigen::Vector3f(x, y_from, 1.0), dir, 0.0f, 1.0f), RayCaster::kMiss)
          << "door of the room at x " << room.interior.x0 << " is blocked at x " << x;
    for (double x : {d.x0 - 0.05, d.x1 + 0.05})
      EXPECT_NE(caster.cast(Eigen::Vector3f(x, y_from, 1.0), dir, 0.0f, 1.0f), RayCaster::kMiss)
          << "no wall beside the door of the room at x " << room.interior.x0 << " (x " << x << ")";
  }
}

// office: a robot of either species gets from the starts into every room (each is a dead end
// behind one door), by the evaluator's flood fill on its default 0.5 m grid: doors lie anywhere
// on that grid, so it must line the body up with them (before, it missed 9 of 41 rooms for
// SLUGCAT and 20 for MR1000, and their surfaces did not count as observable).
TEST(Scenes, OfficeRoomsAreReachableByBothSpecies) {
  const auto layout = detail::office_layout(1);
  const auto scene = generate_scene("office", 1);
  const RayCaster caster(scene.mesh);
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    const std::vector<Eigen::Vector3d> starts = {scene.suggested_starts.front()};
    const auto ground = reachable_ground(caster, species, starts, scene.site);
    size_t rooms_reached = 0;
    for (const auto& room : layout.rooms) {
      bool in = false;
      for (const auto& p : ground) in = in || room.interior.contains(p.x(), p.y());
      rooms_reached += in;
    }
    EXPECT_EQ(rooms_reached, layout.rooms.size()) << species.name;
  }
}

// multi-storey: the tracked robot reaches both upper levels from the starts (ramps and
// stairs), the wheeled robot only the ground level; both get around the ground floor.
TEST(Scenes, MultiStoreyUpperLevelsNeedTheTrackedRobot) {
  const auto scene = generate_scene("multi-storey", 1);
  const RayCaster caster(scene.mesh);
  auto levels = [&](const core::SpeciesConfig& species) {
    const std::vector<Eigen::Vector3d> starts = {scene.suggested_starts.front()};
    std::array<size_t, 3> n{0, 0, 0};
    for (const auto& p : reachable_ground(caster, species, starts, scene.site)) {
      const bool indoors = p.x() > 0.25 && p.x() < 31.75 && p.y() > 0.25 && p.y() < 21.75;
      if (std::abs(p.z() - 6.0) < 0.05) ++n[2];
      else if (std::abs(p.z() - 3.0) < 0.05) ++n[1];
      else if (std::abs(p.z()) < 0.05 && indoors) ++n[0];
    }
    return n;
  };
  const auto tracked = levels(core::builtin_slugcat()), wheeled = levels(core::builtin_mr1000());
  EXPECT_GT(tracked[0], 1000u);
  EXPECT_GT(tracked[1], 1000u);  // level 1 is ~600 m2 of floor: 4 cells per m2
  EXPECT_GT(tracked[2], 1000u);
  EXPECT_GT(wheeled[0], 1000u);
  EXPECT_EQ(wheeled[1], 0u);
  EXPECT_EQ(wheeled[2], 0u);
}

// campus: a site of about 100 m x 100 m, starts along its south edge, six buildings, five of
// them with two or three storeys; every floor of every building is there (a floor right below
// a point 1 m above its level, in the middle of the building).
TEST(Scenes, CampusIsAHundredMetreSiteOfBuildingsWithStoreys) {
  const auto scene = generate_scene("campus", 1);
  EXPECT_NEAR(scene.site.sizes().x(), 100.0, 5.0);
  EXPECT_NEAR(scene.site.sizes().y(), 100.0, 10.0);
  EXPECT_EQ(scene.suggested_starts.size(), 16u);
  for (const auto& s : scene.suggested_starts) EXPECT_TRUE(scene.site.contains(s)) << s.transpose();
  const auto buildings = detail::campus_buildings();
  ASSERT_GE(buildings.size(), 6u);
  const RayCaster caster(scene.mesh);
  int storeyed = 0;
  for (const auto& c : buildings) {
    storeyed += c.floors >= 2;
    const Rect& f = c.footprint;
    for (int k = 0; k < c.floors; ++k) {
      const Eigen::Vector3f above(0.5f * float(f.x0 + f.x1), 0.5f * float(f.y0 + f.y1),
                                  float(c.base_z + k * c.storey_m + 1.0));
      EXPECT_NEAR(caster.cast(above, -Eigen::Vector3f::UnitZ(), 0.0f, 2.0f), 1.0f, 1e-3f) << c.name << " floor " << k;
    }
  }
  EXPECT_GE(storeyed, 5);
}

// campus climbs (every flight between storeys, the parking deck's 16 deg ramp, the lab's plinth
// steps): the quadruped and the SLUGCAT walk or drive up every one to the level above, the
// wheeled MR1000 up none.
TEST(Scenes, CampusClimbsTakeTheQuadrupedAndTheTrackedRobotUpOnly) {
  const auto scene = generate_scene("campus", 1);
  const RayCaster caster(scene.mesh);
  const auto climbs = detail::campus_climbs();
  ASSERT_GE(climbs.size(), 7u);
  for (const auto& climb : climbs) {
    const Eigen::Vector3d start = climb.path.front(), towards = climb.path[1];
    const double yaw = std::atan2(towards.y() - start.y(), towards.x() - start.x());
    for (const auto& species : {core::builtin_quadruped(), core::builtin_slugcat(), core::builtin_mr1000()}) {
      RobotMotion robot(caster, species, start, yaw);
      robot.follow({climb.path.begin() + 1, climb.path.end()});
      for (int i = 0; i < 1200 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1);
      const std::string what = climb.name + " " + species.name + ": " + to_string(robot.block_reason());
      if (species.name == "MR1000") {
        EXPECT_EQ(robot.state(), MotionState::kBlocked) << what;
        EXPECT_LT(robot.ground_position().z(), start.z() + 0.3) << what;
      } else {
        EXPECT_EQ(robot.state(), MotionState::kIdle) << what << " at " << robot.ground_position().transpose();
        EXPECT_NEAR(robot.ground_position().z(), climb.top_z, 1e-3) << what;
      }
    }
  }
}

// campus, who gets where from the south edge: the workshop behind its masonry yard is the
// SLUGCAT's alone; the quadruped and the SLUGCAT reach the lab on its plinth and the upper
// floors; the MR1000 neither, but the ground floors of the other buildings and the streets.
TEST(Scenes, CampusWorkshopIsTheTrackedRobotsAndUpperFloorsTheClimbers) {
  const auto scene = generate_scene("campus", 1);
  const RayCaster caster(scene.mesh);
  const auto buildings = detail::campus_buildings();
  auto inside = [&](const std::string& name, const Eigen::Vector3d& p) {
    for (const auto& c : buildings)
      if (c.name == name) return c.footprint.contains(p.x(), p.y());
    return false;
  };
  struct Reach {
    size_t workshop = 0, lab = 0, upstairs = 0, total = 0;
  };
  auto reach = [&](const core::SpeciesConfig& species) {
    const std::vector<Eigen::Vector3d> starts = {scene.suggested_starts[7]};
    Reach r;
    for (const auto& p : reachable_ground(caster, species, starts, scene.site)) {
      ++r.total;
      r.workshop += inside("workshop", p);
      r.lab += inside("lab", p);
      r.upstairs += p.z() > 3.0;
    }
    return r;
  };
  const Reach tracked = reach(core::builtin_slugcat()), legged = reach(core::builtin_quadruped()),
              wheeled = reach(core::builtin_mr1000());
  EXPECT_GT(tracked.workshop, 500u);
  EXPECT_EQ(legged.workshop, 0u);
  EXPECT_EQ(wheeled.workshop, 0u);
  EXPECT_GT(legged.lab, 1000u);
  EXPECT_GT(tracked.lab, 1000u);
  EXPECT_EQ(wheeled.lab, 0u);
  EXPECT_GT(legged.upstairs, 5000u);
  EXPECT_GT(tracked.upstairs, 5000u);
  EXPECT_EQ(wheeled.upstairs, 0u);
  EXPECT_GT(wheeled.total, 20000u);
}

}  // namespace
}  // namespace hexplore::sim
