#include "common/sim/robot_motion.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "common/sim/building.h"
#include "common/sim/mesh_builder.h"
#include "common/core/rng.h"
#include "common/sim/scene_error.h"
#include "common/sim/scene_parts.h"
#include "common/sim/scenes.h"
#include "common/sim/terrain_probe.h"

namespace hexplore::sim {
namespace {

// Flat ground with, along +x: a staircase (0.175 m risers) at x in [5, ...), and further
// along y = 10 a debris field (0.10-0.20 m cells) at x in [5, 9]; a wall at y = -5.
TriangleMesh test_course() {
  MeshBuilder b;
  b.plane(-10, -10, 30, 20, 0.0);
  b.stairs({5.0, 0.0, 0.0}, Heading::kPlusX, 1.6, 10, 0.175, 0.28);
  b.box({7.8, -0.8, 0}, {12, 0.8, 1.75});  // landing at the top of the stairs
  core::SimRng rng(3);
  detail::debris_field(b, rng, Rect{5, 9, 9, 11}, 0.5, 0.10, 0.20);
  b.box({-10, -5.2, 0}, {30, -5.0, 2.5});
  return b.take();
}

MotionState drive(RobotMotion& robot, std::vector<Eigen::Vector3d> path, double seconds) {
  robot.follow(std::move(path));
  for (double t = 0; t < seconds && robot.state() == MotionState::kMoving; t += 0.05) robot.step(0.05);
  return robot.state();
}

TEST(RobotMotion, FollowsAPathAtItsSpeedOnFlatGround) {
  const RayCaster caster(test_course());
  const auto species = core::builtin_mr1000();
  RobotMotion robot(caster, species, {0, 5, 0}, 0.0);
  robot.follow({{2, 5, 0}, {2, 7, 0}});
  robot.step(1.0);
  EXPECT_EQ(robot.state(), MotionState::kMoving);
  EXPECT_NEAR(robot.odometry_m(), species.speed_mps * 1.0, 1e-6);
  EXPECT_NEAR(robot.velocity().norm(), species.speed_mps, 1e-6);
  for (int i = 0; i < 200 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1);
  EXPECT_EQ(robot.state(), MotionState::kIdle);
  EXPECT_NEAR(robot.odometry_m(), 4.0, 1e-6);
  EXPECT_LT((robot.ground_position() - Eigen::Vector3d(2, 7, 0)).norm(), 1e-5);
  // The body box rests on the ground.
  EXPECT_NEAR(robot.body_pose().translation().z(), species.body_half_extents_m.z(), 1e-5);
}

TEST(RobotMotion, WheeledRobotCannotClimbStairsThatTrackedRobotClimbs) {
  const RayCaster caster(test_course());
  RobotMotion tracked(caster, core::builtin_slugcat(), {2, 0, 0}, 0.0);
  EXPECT_EQ(drive(tracked, {{10, 0, 0}}, 60), MotionState::kIdle) << to_string(tracked.block_reason());
  EXPECT_NEAR(tracked.ground_position().z(), 1.75, 1e-3);

  RobotMotion wheeled(caster, core::builtin_mr1000(), {2, 0, 0}, 0.0);
  EXPECT_EQ(drive(wheeled, {{10, 0, 0}}, 60), MotionState::kBlocked);
  EXPECT_LT(wheeled.ground_position().x(), 5.0);
  EXPECT_NEAR(wheeled.ground_position().z(), 0.0, 1e-6);
}

TEST(RobotMotion, WheeledRobotCannotCrossDebrisThatTrackedRobotCrosses) {
  const RayCaster caster(test_course());
  RobotMotion tracked(caster, core::builtin_slugcat(), {3, 10, 0}, 0.0);
  EXPECT_EQ(drive(tracked, {{11, 10, 0}}, 60), MotionState::kIdle) << to_string(tracked.block_reason());
  RobotMotion wheeled(caster, core::builtin_mr1000(), {3, 10, 0}, 0.0);
  EXPECT_EQ(drive(wheeled, {{11, 10, 0}}, 60), MotionState::kBlocked);
  EXPECT_EQ(wheeled.block_reason(), TerrainVerdict::kStep);
}

TEST(RobotMotion, WallsBlockEverySpecies) {
  const RayCaster caster(test_course());
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    RobotMotion robot(caster, species, {0, -2, 0}, 0.0);
    EXPECT_EQ(drive(robot, {{0, -8, 0}}, 30), MotionState::kBlocked) << species.name;
    EXPECT_EQ(robot.block_reason(), TerrainVerdict::kObstacle);
    EXPECT_GT(robot.ground_position().y(), -5.0 + species.body_half_extents_m.x() - 0.01);
  }
}

TEST(RobotMotion, MultiFloorSupportIsTheNearestBelowNotTheTopmost) {
  MeshBuilder b;
  b.plane(-10, -10, 10, 10, 0.0);
  b.box({-5, -5, 3.0}, {5, 5, 3.2});  // a slab 3 m up: the robot drives under it
  const RayCaster caster(b.take());
  RobotMotion robot(caster, core::builtin_slugcat(), {-8, 0, 0}, 0.0);
  EXPECT_EQ(drive(robot, {{8, 0, 0}}, 60), MotionState::kIdle);
  EXPECT_NEAR(robot.ground_position().z(), 0.0, 1e-6);
  RobotMotion upstairs(caster, core::builtin_slugcat(), {0, 0, 3.2}, 0.0);  // placed on the slab
  EXPECT_NEAR(upstairs.ground_position().z(), 3.2, 1e-6);
  EXPECT_THROW(RobotMotion(caster, core::builtin_slugcat(), {50, 50, 0}, 0.0), SceneError);
}

TEST(RobotMotion, LowCeilingsBlockByClearance) {
  MeshBuilder b;
  b.plane(-10, -10, 10, 10, 0.0);
  b.box({2, -3, 0.6}, {4, 3, 0.8});  // a table top 0.6 m up: under it fits SLUGCAT, not MR1000
  const RayCaster caster(b.take());
  RobotMotion tracked(caster, core::builtin_slugcat(), {0, 0, 0}, 0.0);
  EXPECT_EQ(drive(tracked, {{6, 0, 0}}, 60), MotionState::kIdle) << to_string(tracked.block_reason());
  RobotMotion wheeled(caster, core::builtin_mr1000(), {0, 0, 0}, 0.0);
  EXPECT_EQ(drive(wheeled, {{6, 0, 0}}, 60), MotionState::kBlocked);
}

TEST(RobotMotion, StopsAndEmergencyStops) {
  const RayCaster caster(test_course());
  RobotMotion robot(caster, core::builtin_mr1000(), {0, 5, 0}, 0.0);
  robot.follow({{3, 5, 0}});
  robot.step(0.5);
  robot.stop();
  const double at = robot.odometry_m();
  robot.step(1.0);
  EXPECT_EQ(robot.state(), MotionState::kStopped);
  EXPECT_EQ(robot.odometry_m(), at);
  robot.emergency_stop();
  robot.follow({{3, 5, 0}});  // ignored until released
  robot.step(1.0);
  EXPECT_EQ(robot.state(), MotionState::kEmergencyStop);
  EXPECT_EQ(robot.odometry_m(), at);
  robot.release();
  robot.follow({{3, 5, 0}});
  robot.step(1.0);
  EXPECT_GT(robot.odometry_m(), at);
}

TEST(RobotMotion, ContactsWithTeammatesAreCountedOncePerContact) {
  const RayCaster caster(test_course());
  RobotMotion robot(caster, core::builtin_mr1000(), {0, 5, 0}, 0.0, /*id=*/1);
  ProxyBox mate;
  mate.id = 2;
  mate.center = {2.0, 5.0, 0.4};
  mate.half_extents = {0.5, 0.35, 0.4};
  const std::vector<ProxyBox> mates = {mate};
  robot.follow({{4, 5, 0}});
  for (int i = 0; i < 100 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1, mates);
  EXPECT_EQ(robot.collisions(), 1u);  // drove through the proxy: one contact, not one per step
}

// A dead-end corridor 1.0 m wide along -y (walls x in [-0.7, -0.5] and [0.5, 0.7], closed at
// y = -6): wide enough for every body, too narrow for either to turn in place.
TriangleMesh dead_end() {
  MeshBuilder b;
  b.plane(-5, -10, 5, 5, 0.0);
  b.box({-0.7, -6.2, 0}, {-0.5, 0, 1.5});
  b.box({0.5, -6.2, 0}, {0.7, 0, 1.5});
  b.box({-0.7, -6.2, 0}, {0.7, -6.0, 1.5});
  return b.take();
}

// A robot nosed into the end of a dead end backs out: it cannot turn where it stands (a body
// turning through the walls was the sim's old shortcut), so it reverses, heading unchanged.
TEST(RobotMotion, NosedIntoADeadEndBacksOut) {
  const RayCaster caster(dead_end());
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    RobotMotion robot(caster, species, {0, -1, 0}, -M_PI / 2);
    EXPECT_EQ(drive(robot, {{0, -8, 0}}, 60), MotionState::kBlocked) << species.name;
    EXPECT_EQ(robot.block_reason(), TerrainVerdict::kObstacle) << species.name;
    EXPECT_LT(robot.ground_position().y(), -5.0) << species.name;
    robot.follow({{0, -1, 0}});
    robot.step(0.5);
    EXPECT_EQ(robot.state(), MotionState::kMoving) << species.name;
    EXPECT_TRUE(robot.reversing()) << species.name;
    for (double t = 0; t < 60 && robot.state() == MotionState::kMoving; t += 0.1) robot.step(0.1);
    EXPECT_EQ(robot.state(), MotionState::kIdle) << species.name << ": " << to_string(robot.block_reason());
    EXPECT_NEAR(robot.ground_position().y(), -1.0, 1e-3) << species.name;
    // Still facing the dead end: it never turned.
    const Eigen::Vector3d forward = robot.body_pose().linear().col(0);
    EXPECT_LT(forward.y(), -0.99) << species.name;
  }
}

// Backing up the way it came to find room to turn, a body never backs into a teammate that
// came up behind it meanwhile (multi-building seed 2: a SLUGCAT that could not turn backed
// into the MR1000 yielding behind it; the safety layer had approved the path ahead, not that).
TEST(RobotMotion, BackingUpToTurnStopsShortOfATeammateBehind) {
  const RayCaster caster(dead_end());
  RobotMotion robot(caster, core::builtin_slugcat(), {0, 1, 0}, -M_PI / 2, /*id=*/1);
  ASSERT_EQ(drive(robot, {{0, -3, 0}}, 30), MotionState::kIdle);
  ProxyBox mate;  // an MR1000 just behind, 0.1 m clear of the SLUGCAT's back
  mate.id = 2;
  mate.center = {0.0, -3.0 + 0.45 + 0.1 + 0.5, 0.4};
  mate.half_extents = {0.35, 0.5, 0.4};
  const std::vector<ProxyBox> mates = {mate};
  // Sideways through the wall: it cannot turn either way in the corridor, so it would back up.
  robot.follow({{3, -3, 0}});
  for (double t = 0; t < 20 && robot.state() == MotionState::kMoving; t += 0.1) robot.step(0.1, mates);
  EXPECT_EQ(robot.collisions(), 0u);
  EXPECT_EQ(robot.state(), MotionState::kBlocked);
  EXPECT_LT(robot.ground_position().y() + 0.45, mate.center.y() - mate.half_extents.y());  // its back short of the mate
}

// In the open the body turns in place to face a waypoint behind it and drives forward.
TEST(RobotMotion, TurnsInPlaceWhereItFits) {
  const RayCaster caster(test_course());
  RobotMotion robot(caster, core::builtin_slugcat(), {0, 5, 0}, 0.0);
  robot.follow({{-3, 5, 0}});
  robot.step(0.1);
  EXPECT_FALSE(robot.reversing());
  EXPECT_EQ(drive(robot, {{-3, 5, 0}}, 30), MotionState::kIdle);
  EXPECT_LT(robot.body_pose().linear().col(0).x(), -0.99);
}

// On the edge of the ground (half a metre from where the plane ends, the centre of the last
// row of ground supervoxels) the wheeled body cannot turn in place: every yaw that faces it
// inwards swings a corner over the edge. It manoeuvres inwards instead (small turns and moves;
// for a waypoint beyond the manoeuvre's reach, towards a stand-in on the way; a main-job run's
// MR1000 stood BLOCKED 0.47 m from the west edge of the default scene for 470 s, not traced). One body
// radius in (where the planner's clearance puts waypoints by the rim of the known ground,
// common/highlevel/clearance.h) it simply turns and drives away.
TEST(RobotMotion, OnTheEdgeOfTheGroundTheWheeledBodyManoeuvresWhereItCannotTurn) {
  const RayCaster caster(test_course());  // the plane ends at y = -10; a wall stands at y = -5
  const auto species = core::builtin_mr1000();
  const TerrainProbe probe(caster, species);
  for (const double from_edge : {0.47, 0.5}) {
    const Footprint start = *probe.footprint({20, -10 + from_edge}, 0.0, 0.0);
    EXPECT_FALSE(probe.turn(start, M_PI / 2).has_value()) << from_edge;
    // Waypoints 2.0, 3.5 and 4.2 m away: within the manoeuvre's reach and beyond it.
    for (const Eigen::Vector3d& goal : {Eigen::Vector3d(20, -7.5, 0), Eigen::Vector3d(20, -6, 0), Eigen::Vector3d(22.5, -6.2, 0)}) {
      RobotMotion on_edge(caster, species, {20, -10 + from_edge, 0}, 0.0);
      EXPECT_EQ(drive(on_edge, {goal}, 90), MotionState::kIdle)
          << from_edge << " to " << goal.transpose() << ": " << to_string(on_edge.block_reason()) << " at "
          << on_edge.ground_position().transpose();
      EXPECT_LT((on_edge.ground_position() - goal).norm(), 0.1) << from_edge << " to " << goal.transpose();
      EXPECT_GE(on_edge.maneuvers(), 1u) << from_edge << " to " << goal.transpose();
    }
  }
  const double radius = species.body_half_extents_m.head<2>().norm();
  RobotMotion inside(caster, species, {20, -10 + radius, 0}, 0.0);
  EXPECT_EQ(drive(inside, {{20, -6, 0}}, 20), MotionState::kIdle);
  EXPECT_LT((inside.ground_position() - Eigen::Vector3d(20, -6, 0)).norm(), 0.1);
  EXPECT_EQ(inside.maneuvers(), 0u);
}

// The safety layer re-sends the remaining path every cycle, starting at the nearest point of
// the path when the robot strayed from it a little. The robot steers for the point after it
// instead of turning aside to a point centimetres away (which made robots jitter in place
// next to obstacles where that turn was blocked and undone every cycle).
TEST(RobotMotion, PathsStartingBesideTheRobotAreJoinedNotTurnedTo) {
  const RayCaster caster(test_course());
  RobotMotion robot(caster, core::builtin_slugcat(), {0, 5, 0}, 0.0);
  for (int cycle = 0; cycle < 20; ++cycle) {
    const Eigen::Vector3d at = robot.ground_position();
    robot.follow({at, {at.x(), 5.1, 0}, {6, 5.1, 0}});
    robot.step(0.1);
    EXPECT_GT(robot.body_pose().linear().col(0).x(), 0.99) << cycle;
  }
  EXPECT_NEAR(robot.odometry_m(), 20 * 0.1 * core::builtin_slugcat().speed_mps, 1e-6);
}

// A vehicle body on its wheels: its underside (0.30 m) is above SLUGCAT's step height and
// below its body height. Turning next to it must not swing part of the body under it (the
// old sim took the underside for ground there and then pinned the robot: every way out was
// a "step" down from it). The robot stays on the ground, out of the vehicle, and can leave.
TEST(RobotMotion, TurningNextToAnOverhangNeverPutsTheBodyUnderIt) {
  MeshBuilder b;
  b.plane(-10, -10, 10, 10, 0.0);
  b.box({0, 0, 0.30}, {4, 2, 1.2});
  const RayCaster caster(b.take());
  ProxyBox vehicle;
  vehicle.id = 99;
  vehicle.center = {2, 1, 0.75};
  vehicle.half_extents = {2, 1, 0.45};
  const auto species = core::builtin_slugcat();
  for (const Eigen::Vector3d& goal : {Eigen::Vector3d(2, -3, 0), Eigen::Vector3d(2.5, 3, 0), Eigen::Vector3d(-1, -2, 0)}) {
    RobotMotion robot(caster, species, {2, -0.4, 0}, 0.0);
    robot.follow({goal});
    for (double t = 0; t < 30 && robot.state() == MotionState::kMoving; t += 0.1) {
      robot.step(0.1);
      EXPECT_NEAR(robot.ground_position().z(), 0.0, 1e-6) << "towards " << goal.transpose();
      EXPECT_FALSE(boxes_overlap(robot.body_box(), vehicle)) << "towards " << goal.transpose();
    }
    // Wherever it ended, it can leave: along the vehicle (reversing if it cannot turn), then away.
    EXPECT_EQ(drive(robot, {{-1, robot.ground_position().y(), 0}, {-3, -3, 0}}, 60), MotionState::kIdle)
        << "after " << goal.transpose() << ": " << to_string(robot.block_reason()) << " at "
        << robot.ground_position().transpose() << " facing " << robot.body_pose().linear().col(0).transpose();
  }
}

TEST(SimClock, AdvancesBySteps) {
  SimClock clock(2.0);
  clock.step(100'000'000);
  clock.step(100'000'000);
  EXPECT_EQ(clock.now_ns(), 200'000'000);
  EXPECT_EQ(clock.wall_period_ns(100'000'000), 50'000'000);
  EXPECT_EQ(SimClock(0.0).wall_period_ns(100'000'000), 0);
}

TEST(Trajectory, LengthOfAPolyline) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}};
  EXPECT_DOUBLE_EQ(trajectory_length(pts), 7.0);
}

// In the single-building scene the annex door lies behind the debris yard: the tracked
// robot gets from the yard gap to the annex door, the wheeled robot does not.
TEST(RobotMotion, SingleBuildingDebrisYardNeedsTheTrackedRobot) {
  const auto scene = generate_scene("single-building", 1);
  const RayCaster caster(scene.mesh);
  const std::vector<Eigen::Vector3d> path = {{29.25, 23.0, 0}, {29.25, 19.0, 0}, {27.2, 16.5, 0}, {27.2, 12.0, 0}};
  RobotMotion tracked(caster, core::builtin_slugcat(), {29.25, 24.0, 0}, -M_PI / 2);
  EXPECT_EQ(drive(tracked, path, 120), MotionState::kIdle) << to_string(tracked.block_reason()) << " at "
                                                           << tracked.ground_position().transpose();
  RobotMotion wheeled(caster, core::builtin_mr1000(), {29.25, 24.0, 0}, -M_PI / 2);
  EXPECT_EQ(drive(wheeled, path, 120), MotionState::kBlocked);
  EXPECT_GT(wheeled.ground_position().y(), 20.5);
}


// The multi-storey scene's ramps (16 and 18 deg) and stairs (0.176 m risers) between its
// floors: the tracked robot drives up every one of them to the floor above, the wheeled robot
// up none (slope limit 12 deg, step limit 0.08 m).
TEST(RobotMotion, MultiStoreyClimbsTakeTheTrackedRobotUpstairsOnly) {
  const auto scene = generate_scene("multi-storey", 1);
  const RayCaster caster(scene.mesh);
  for (const auto& climb : detail::multi_storey_climbs()) {
    const Eigen::Vector3d start = climb.path.front(), towards = climb.path[1];
    const double yaw = std::atan2(towards.y() - start.y(), towards.x() - start.x());
    const std::vector<Eigen::Vector3d> rest(climb.path.begin() + 1, climb.path.end());
    RobotMotion tracked(caster, core::builtin_slugcat(), start, yaw);
    EXPECT_EQ(drive(tracked, rest, 120), MotionState::kIdle)
        << climb.name << ": " << to_string(tracked.block_reason()) << " at " << tracked.ground_position().transpose();
    EXPECT_NEAR(tracked.ground_position().z(), climb.top_z, 1e-3) << climb.name;
    RobotMotion wheeled(caster, core::builtin_mr1000(), start, yaw);
    EXPECT_EQ(drive(wheeled, rest, 120), MotionState::kBlocked) << climb.name;
    EXPECT_LT(wheeled.ground_position().z(), start.z() + 0.3) << climb.name;  // its front edge may be on the foot
  }
}


// office: the wheeled robot drives from the corridor through the door of the narrowest room
// (lined up with the door, which is only 0.2-0.3 m wider than the body), turns round inside
// and leaves again; the room is a dead end, so it must turn (or reverse) where it is small.
TEST(RobotMotion, WheeledRobotTurnsRoundInTheNarrowestOfficeRoom) {
  const auto layout = detail::office_layout(1);
  const auto scene = generate_scene("office", 1);
  const RayCaster caster(scene.mesh);
  const auto narrowest = std::min_element(layout.rooms.begin(), layout.rooms.end(), [](const auto& a, const auto& b) {
    return a.interior.x1 - a.interior.x0 < b.interior.x1 - b.interior.x0;
  });
  const auto& room = *narrowest;
  EXPECT_LT(room.interior.x1 - room.interior.x0, 3.0);
  const double door_x = 0.5 * (room.door.x0 + room.door.x1), wall_y = 0.5 * (room.door.y0 + room.door.y1);
  const double into = room.door_faces_north ? -1.0 : 1.0;  // from the door wall into the room
  const Eigen::Vector3d corridor(door_x, wall_y - into * 0.9, 0), doorway(door_x, wall_y + into * 0.9, 0);
  const Eigen::Vector3d inside(0.5 * (room.interior.x0 + room.interior.x1), 0.5 * (room.interior.y0 + room.interior.y1), 0);
  RobotMotion robot(caster, core::builtin_mr1000(), corridor, std::atan2(into, 0.0));
  EXPECT_EQ(drive(robot, {doorway, inside}, 60), MotionState::kIdle)
      << "in: " << to_string(robot.block_reason()) << " at " << robot.ground_position().transpose();
  EXPECT_TRUE(room.interior.contains(robot.ground_position().x(), robot.ground_position().y()));
  EXPECT_EQ(drive(robot, {doorway, corridor}, 60), MotionState::kIdle)
      << "out: " << to_string(robot.block_reason()) << " at " << robot.ground_position().transpose();
  EXPECT_LT((robot.ground_position() - corridor).norm(), 1e-3);
  // Leaving at a slant instead (what a path through waypoints off the door's axis asks for)
  // runs into the jamb; the body manoeuvres through the door instead of stopping there.
  RobotMotion slant(caster, core::builtin_mr1000(), inside, std::atan2(-into, 0.0));
  const Eigen::Vector3d aside(door_x + 0.9, wall_y - into * 0.9, 0);
  EXPECT_EQ(drive(slant, {aside}, 60), MotionState::kIdle)
      << to_string(slant.block_reason()) << " at " << slant.ground_position().transpose();
  EXPECT_GE(slant.maneuvers(), 1u);
  EXPECT_LT((slant.ground_position() - aside).head<2>().norm(), 0.1);  // a manoeuvre's reach
}

// office, seed 1: the SLUGCAT stood at the door of a room for 300 s (lockstep mission, from
// 874 s on): every path out came to the door past a waypoint beside its jamb, the straight line
// on clipped the jamb, and there was no room to turn there. It now manoeuvres out; a teammate
// in the way or a waypoint no manoeuvre reaches (inside a wall) still leaves it BLOCKED.
TEST(RobotMotion, ABodyWedgedBesideADoorJambManoeuvresOut) {
  const auto layout = detail::office_layout(1);
  const auto scene = generate_scene("office", 1);
  const RayCaster caster(scene.mesh);
  const auto& room = layout.rooms.front();  // the south-west room; its door faces north
  ASSERT_TRUE(room.door_faces_north);
  const double wall_y = 0.5 * (room.door.y0 + room.door.y1);
  const double beside_jamb = room.door.x1 - 0.1;
  const Eigen::Vector3d inside(beside_jamb + 0.8, wall_y - 1.3, 0), by_jamb(beside_jamb, wall_y - 0.6, 0);
  const Eigen::Vector3d corridor(beside_jamb, wall_y + 0.6, 0), along(beside_jamb - 5.0, wall_y + 1.0, 0);
  for (double yaw_deg : {90.0, 135.0, 180.0}) {
    RobotMotion robot(caster, core::builtin_slugcat(), inside, yaw_deg * M_PI / 180);
    EXPECT_EQ(drive(robot, {by_jamb, corridor, along}, 60), MotionState::kIdle)
        << yaw_deg << ": " << to_string(robot.block_reason()) << " at " << robot.ground_position().transpose();
    EXPECT_GE(robot.maneuvers(), 1u) << yaw_deg;
  }
  // A teammate standing in the doorway's way out: the manoeuvre keeps clear of its body (no
  // contact), and the robot is blocked there instead.
  ProxyBox mate;
  mate.id = 7;
  mate.center = Eigen::Vector3d(0.5 * (room.door.x0 + room.door.x1), wall_y + 0.9, 0.4);
  mate.half_extents = core::builtin_mr1000().body_half_extents_m;
  RobotMotion blocked(caster, core::builtin_slugcat(), inside, M_PI / 2);
  blocked.follow({by_jamb, corridor, along});
  for (double t = 0; t < 60 && blocked.state() == MotionState::kMoving; t += 0.05) blocked.step(0.05, {&mate, 1});
  EXPECT_EQ(blocked.state(), MotionState::kBlocked);
  EXPECT_EQ(blocked.collisions(), 0u);
  RobotMotion robot(caster, core::builtin_slugcat(), inside, M_PI / 2);
  const Eigen::Vector3d in_the_wall(room.door.x1 + 0.5, wall_y, 0);
  EXPECT_EQ(drive(robot, {by_jamb, in_the_wall}, 60), MotionState::kBlocked);
  EXPECT_EQ(robot.maneuvers(), 0u);  // searched once, found nothing
}

}  // namespace
}  // namespace hexplore::sim
