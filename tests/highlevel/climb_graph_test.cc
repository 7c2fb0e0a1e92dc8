// Ramps and stairs as the tracked robot maps them: a SLUGCAT drives up each climb of the
// multi-storey scene in the motion model, scanning with its simulated LiDAR; the scans go
// through the perception map, the supervoxel segmentation and the topology graph. The climb
// must come out as ground the tracked species may use, connecting the floor below to the
// floor above, and closed to the wheeled species. (With the perception map as it was, the
// flights came out cut: treads seen from the top landing turned into ceilings, the foot of
// every riser read as an overhang, and voxel slopes of 35-45 deg on a 30 deg flight were
// high risk for a 35 deg species.)

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/highlevel/clearance.h"
#include "common/highlevel/high_level_map.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/segmenter.h"
#include "common/perception/perception_map.h"
#include "common/perception/voxel_proto.h"
#include "common/planning/frontier.h"
#include "common/sim/lidar.h"
#include "common/sim/robot_motion.h"
#include "common/sim/scene_parts.h"
#include "common/sim/scenes.h"

namespace hexplore {
namespace {

constexpr int kSlugcat = 0;  // species indices of the team {SLUGCAT, MR1000}
constexpr int kMr1000 = 1;

// The high-level map of what a robot of team[driver] saw driving `climb`, scanning every half
// metre with its first LiDAR; with stop_below_top_m >= 0, only until its ground is that far
// below the climb's top.
highlevel::HighLevelMap map_of_climb(const sim::RayCaster& caster, const sim::detail::Climb& climb,
                                     const std::vector<core::SpeciesConfig>& team, size_t driver,
                                     double stop_below_top_m = -1.0, highlevel::ClearanceOptions clearance = {}) {
  const core::SpeciesConfig& species = team[driver];
  perception::PerceptionMap map(perception::make_map_params(core::AlgorithmParams{}, team, species));
  sim::LidarModel lidar(species.lidars[0], 7);
  const Eigen::Vector3d start = climb.path.front();
  sim::RobotMotion robot(caster, species, start, std::atan2(climb.path[1].y() - start.y(), climb.path[1].x() - start.x()));
  robot.follow({climb.path.begin() + 1, climb.path.end()});
  std::vector<float> xyz;
  double scanned_at = -1.0;
  for (int i = 0; i < 4000 && robot.state() == sim::MotionState::kMoving; ++i) {
    if (stop_below_top_m >= 0.0 && robot.ground_position().z() >= climb.top_z - stop_below_top_m) break;
    robot.step(0.05);
    if (robot.odometry_m() - scanned_at < 0.5 && robot.state() == sim::MotionState::kMoving) continue;
    scanned_at = robot.odometry_m();
    const auto scan = lidar.scan(caster, robot.body_pose());
    xyz.clear();
    for (const auto& p : scan.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    perception::ScanPoints points;
    points.sensor_origin = scan.origin;
    points.xyz = xyz.data();
    points.count = scan.points.size();
    map.integrate(points, {});
  }
  if (stop_below_top_m < 0.0) {
    EXPECT_NEAR(robot.ground_position().z(), climb.top_z, 1e-3) << climb.name << ": the robot did not get up";
  }

  // Voxels as the hlmap service receives them (through the wire message), one full update.
  std::vector<highlevel::VoxelSample> samples;
  for (const auto& v : map.voxels()) {
    v1::Voxel wire;
    perception::to_proto(v, &wire);
    samples.push_back(highlevel::from_proto(wire));
  }
  std::vector<int> levels;
  for (const auto& s : team) levels.push_back(s.traversal_level);
  highlevel::SupervoxelSegmenter segmenter(highlevel::SegmenterParams{}, levels);
  segmenter.update(samples);
  highlevel::MapUpdate update;
  update.full_snapshot = true;
  for (const auto& [key, sv] : segmenter.supervoxels()) update.upserts.push_back(sv);
  update.edge_upserts = segmenter.edges();
  highlevel::HighLevelMap hl(levels, clearance);
  hl.apply(update);
  return hl;
}

// Horizontal distance from p to the climb's path (the flight or ramp runs along it).
double off_path(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& path) {
  double best = 1e9;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d a = path[i].head<2>(), ab = path[i + 1].head<2>() - a;
    const double t = std::clamp((p.head<2>() - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p.head<2>() - (a + t * ab)).norm());
  }
  return best;
}

std::string at(const highlevel::TopologyGraph& g, uint64_t key) {
  std::ostringstream s;
  s << g.position(key)->transpose();
  return s.str();
}

TEST(ClimbGraph, MultiStoreyRampsAndStairsConnectTheFloorsForTheTrackedSpeciesOnly) {
  const auto scene = sim::generate_scene("multi-storey", 1);
  const sim::RayCaster caster(scene.mesh);
  for (const auto& climb : sim::detail::multi_storey_climbs()) {
    const auto hl = map_of_climb(caster, climb, {core::builtin_slugcat(), core::builtin_mr1000()}, kSlugcat);
    const auto& g = hl.graph();
    const Eigen::Vector3d below = climb.path.front(), above = climb.path.back() + Eigen::Vector3d(0, 0, climb.top_z - below.z());
    const auto from = g.nearest(below, kSlugcat), to = g.nearest(above, kSlugcat);
    ASSERT_TRUE(from && to) << climb.name;
    EXPECT_LT((*g.position(*from) - below).norm(), 1.0) << climb.name;
    EXPECT_LT((*g.position(*to) - above).norm(), 1.0) << climb.name;
    const double d = g.dist(*from, *to, kSlugcat);
    EXPECT_LT(d, 2.0 * sim::trajectory_length(climb.path)) << climb.name << ": no path from " << at(g, *from) << " to " << at(g, *to);
    // The climb itself is tracked-only ground: every vertex on it between the floors.
    int between = 0;
    for (uint64_t key : g.vertex_keys()) {
      const Eigen::Vector3d p = *g.position(key);
      if (p.z() < below.z() + 0.5 || p.z() > climb.top_z - 0.5 || off_path(p, climb.path) > 1.3) continue;
      ++between;
      EXPECT_FALSE(g.passable(key, kMr1000)) << climb.name << " at " << at(g, key);
    }
    EXPECT_GT(between, 5) << climb.name;
    const auto wheeled_from = g.nearest(below, kMr1000);
    if (wheeled_from) {
      EXPECT_EQ(g.dist(*wheeled_from, *to, kMr1000), highlevel::TopologyGraph::kUnreachable) << climb.name;
    }
  }
}

// B1's flight in the multi-building scene: 17 risers from y = 5 along x = 3, floors at 0 and 3 m.
sim::detail::Climb multi_building_b1_flight() {
  return {"B1 flight", {{3.0, 3.0, 0}, {3.0, 5.0 + 17 * 0.28 + 1.5, 0}}, 3.0};
}

// The multi-building scene's flights (17-23 risers of 0.17-0.18 m on 0.28 m treads, 32 deg)
// as the tracked robot maps them driving up B1's: it joins the ground floor to the upper one.
// No robot climbed any flight in the multi-building missions of stops 56-57, and every
// observable sample those missions never mapped was upstairs (tools/unseen); driven up, the
// flight is ground of the graph, so what keeps robots off it is before the climb (below).
TEST(ClimbGraph, MultiBuildingFlightConnectsTheFloorsForTheTrackedSpecies) {
  const auto scene = sim::generate_scene("multi-building", 1);
  const sim::RayCaster caster(scene.mesh);
  const sim::detail::Climb flight = multi_building_b1_flight();
  const auto hl = map_of_climb(caster, flight, {core::builtin_slugcat(), core::builtin_mr1000()}, kSlugcat);
  const auto& g = hl.graph();
  const Eigen::Vector3d below = flight.path.front(), above = flight.path.back() + Eigen::Vector3d(0, 0, flight.top_z);
  const auto from = g.nearest(below, kSlugcat), to = g.nearest(above, kSlugcat);
  ASSERT_TRUE(from && to);
  EXPECT_LT((*g.position(*from) - below).norm(), 1.0);
  EXPECT_LT((*g.position(*to) - above).norm(), 1.0) << "nearest vertex " << at(g, *to);
  EXPECT_LT(g.dist(*from, *to, kSlugcat), 2.0 * sim::trajectory_length(flight.path))
      << "no path from " << at(g, *from) << " to " << at(g, *to);
}

// Seen from its foot, B1's flight is SLUGCAT ground up to about 0.7 m, then risers that read as
// walls, then more sloped ground the graph did not join: in stop 57's map the highest reachable
// tread was 0.72 m up and none was at the frontier, so nothing ever sent a tracked robot up. On
// the planning map the flight's pieces are bridged across the risers and a wall uphill of the
// known flight is its frontier (common/highlevel/slopes.h): wherever the robot stands on the
// way up, the graph reaches further up the flight than it stands, and there is a frontier up
// there to draw it on (stop 58: from the foot the graph reaches 2.17 m, its frontier too), one
// a view may stand at (room for the SLUGCAT's body: stop 58's flights had none, their risers
// and the slab over them read as walls; stop 59: steps and ceilings are not in the way). "Above"
// is at least 0.15 m higher: a quarter metre further up the 33 deg flight.
TEST(ClimbGraph, MultiBuildingFlightDrawsTheTrackedRobotUpFromItsFoot) {
  const auto scene = sim::generate_scene("multi-building", 1);
  const sim::RayCaster caster(scene.mesh);
  const std::vector<core::SpeciesConfig> team = {core::builtin_slugcat(), core::builtin_mr1000()};
  core::TeamConfig team_config;
  team_config.species = team;
  const highlevel::ClearanceOptions clearance = highlevel::clearance_options(team_config);  // planning's map
  const Eigen::AlignedBox3d region(Eigen::Vector3d(-1, -1, -0.5), Eigen::Vector3d(40.4, 40.4, 14.0));  // multi-building.yaml
  const sim::detail::Climb flight = multi_building_b1_flight();
  for (double stop_below_top_m : {2.9, 2.3, 1.7, 1.1, 0.5}) {
    const double stands_at = flight.top_z - stop_below_top_m;
    const auto hl = map_of_climb(caster, flight, team, kSlugcat, stop_below_top_m, clearance);
    const auto& g = hl.graph();
    const auto foot = g.nearest(flight.path.front(), kSlugcat);
    ASSERT_TRUE(foot);
    double highest_frontier = -1.0;
    for (uint64_t key : g.vertex_keys()) {
      const Eigen::Vector3d p = *g.position(key);
      if (off_path(p, flight.path) > 1.0 || p.y() < 4.5 || !g.passable(key, kSlugcat)) continue;
      if (g.dist(*foot, key, kSlugcat) == highlevel::TopologyGraph::kUnreachable) continue;
      if (!g.room_to_stand(key, kSlugcat)) continue;  // no view stands there
      if (planning::at_frontier(hl, *hl.find(key), region)) highest_frontier = std::max(highest_frontier, p.z());
    }
    EXPECT_GT(highest_frontier, stands_at + 0.15) << "standing " << stands_at << " m up the flight, no frontier above it is reachable";
  }
}

// Ramp B's crest hides the roof deck from a sensor on the ramp until the robot is within about
// a metre of the top: mapped from 1 m below the top, the graph ends at the crest, and only the
// frontier (the rim of the known ground, common/planning/frontier.h) says there is more to see
// there. From 0.3 m below the top the roof is ground of the graph, joined to the ramp.
TEST(ClimbGraph, RampBCrestIsAFrontierUntilTheRobotIsNearlyAtTheTop) {
  const auto scene = sim::generate_scene("multi-storey", 1);
  const sim::RayCaster caster(scene.mesh);
  const auto climbs = sim::detail::multi_storey_climbs();
  const auto& ramp_b = climbs[2];
  ASSERT_EQ(ramp_b.name.substr(0, 6), "ramp B");
  const std::vector<core::SpeciesConfig> team = {core::builtin_slugcat(), core::builtin_mr1000()};
  core::TeamConfig team_config;
  team_config.species = team;
  const highlevel::ClearanceOptions clearance = highlevel::clearance_options(team_config);  // planning's map
  const Eigen::AlignedBox3d region(Eigen::Vector3d(-2, -5, -0.5), Eigen::Vector3d(34, 27, 7.5));  // multi-storey.yaml
  const Eigen::Vector3d crest(17.77, 20.5, 6.0), roof(15.5, 20.5, 6.0);

  const auto below = map_of_climb(caster, ramp_b, team, kSlugcat, /*stop_below_top_m=*/1.0, clearance);
  const auto& g = below.graph();
  const auto near_crest = g.nearest(crest, kSlugcat);
  ASSERT_TRUE(near_crest);
  EXPECT_LT((*g.position(*near_crest) - crest).norm(), 0.6) << at(g, *near_crest);
  for (uint64_t key : g.vertex_keys()) {
    if (g.position(key)->z() <= 5.9 || g.position(key)->y() <= 18.5) continue;
    EXPECT_GT(g.position(key)->x(), 17.5) << "roof ground mapped from below the crest at " << at(g, key);
  }
  int frontier = 0;
  for (uint64_t key : g.vertex_keys()) {
    const Eigen::Vector3d p = *g.position(key);
    if (p.x() < 18.2 && p.z() > 5.7) frontier += planning::at_frontier(below, *below.find(key), region) ? 1 : 0;
  }
  EXPECT_GE(frontier, 1) << "the crest is not at the frontier";

  const auto top = map_of_climb(caster, ramp_b, team, kSlugcat, /*stop_below_top_m=*/0.3, clearance);
  const auto& t = top.graph();
  const auto on_roof = t.nearest(roof, kSlugcat), on_ramp = t.nearest(Eigen::Vector3d(20.3, 20.5, 5.2), kSlugcat);
  ASSERT_TRUE(on_roof && on_ramp);
  EXPECT_LT((*t.position(*on_roof) - roof).norm(), 1.0) << at(t, *on_roof);
  EXPECT_LT(t.dist(*on_ramp, *on_roof, kSlugcat), highlevel::TopologyGraph::kUnreachable) << "no path from " << at(t, *on_ramp) << " to " << at(t, *on_roof);
}

// The campus flights (0.148 m risers, 26 deg), its parking deck's 16 deg ramp and the lab's
// plinth steps as the quadruped maps them with its own LiDAR, in a team of the three built-in
// species (SLUGCAT raised to level 3, as the campus team files do): each joins the level below
// to the level above for the quadruped and for the SLUGCAT, and none of it is the MR1000's.
// (The older scenes' 0.175 m risers at 30-32 deg do not join for the quadruped: its map reads
// steps above its 0.20 m there.)
TEST(ClimbGraph, CampusClimbsConnectTheLevelsForTheQuadrupedAndTheTrackedSpecies) {
  constexpr int kTracked = 0, kLegged = 1, kWheeled = 2;
  core::SpeciesConfig slugcat = core::builtin_slugcat();
  slugcat.traversal_level = 3;
  const std::vector<core::SpeciesConfig> team = {slugcat, core::builtin_quadruped(), core::builtin_mr1000()};
  const auto scene = sim::generate_scene("campus", 1);
  const sim::RayCaster caster(scene.mesh);
  for (const auto& climb : sim::detail::campus_climbs()) {
    const auto hl = map_of_climb(caster, climb, team, kLegged);
    const auto& g = hl.graph();
    const Eigen::Vector3d below = climb.path.front(), above = climb.path.back() + Eigen::Vector3d(0, 0, climb.top_z - below.z());
    const auto from = g.nearest(below, kLegged), to = g.nearest(above, kLegged);
    ASSERT_TRUE(from && to) << climb.name;
    EXPECT_LT((*g.position(*from) - below).norm(), 1.0) << climb.name;
    EXPECT_LT((*g.position(*to) - above).norm(), 1.0) << climb.name;
    for (int k : {kLegged, kTracked})
      EXPECT_LT(g.dist(*from, *to, k), 2.0 * sim::trajectory_length(climb.path))
          << climb.name << " species " << k << ": no path from " << at(g, *from) << " to " << at(g, *to);
    for (uint64_t key : g.vertex_keys()) {
      const Eigen::Vector3d p = *g.position(key);
      if (p.z() < below.z() + 0.3 || p.z() > climb.top_z - 0.3 || off_path(p, climb.path) > 0.6) continue;
      EXPECT_FALSE(g.passable(key, kWheeled)) << climb.name << " at " << at(g, key);
    }
    const auto wheeled_from = g.nearest(below, kWheeled);
    if (wheeled_from) {
      EXPECT_EQ(g.dist(*wheeled_from, *to, kWheeled), highlevel::TopologyGraph::kUnreachable) << climb.name;
    }
  }
}

}  // namespace
}  // namespace hexplore
