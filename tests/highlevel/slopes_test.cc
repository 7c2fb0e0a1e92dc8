// A flight of stairs seen from its foot, reduced to supervoxels: sloped ground pieces on one
// plane with a riser (a facade) between them and no shared edge across it (slopes.h).

#include "common/highlevel/slopes.h"

#include <cmath>

#include <gtest/gtest.h>

#include "common/highlevel/high_level_map.h"

namespace hexplore::highlevel {
namespace {

constexpr double kFlightDeg = 32.0;  // the built-in scenes' flights: 0.17-0.18 m risers on 0.28 m treads

// The flight's plane rises along +y: ground centred at (x, y) on it.
Supervoxel flight_piece(int i, int j, double x, double y) {
  const double t = std::tan(kFlightDeg * M_PI / 180.0);
  Supervoxel g;
  g.key = supervoxel_key({i, j, 0}, SurfaceClass::kGround);
  g.center = {x, y, t * y};
  g.normal = Eigen::Vector3d(0, -std::sin(kFlightDeg * M_PI / 180.0), std::cos(kFlightDeg * M_PI / 180.0));
  g.surface = SurfaceClass::kGround;
  g.traversal_requirement = 2;
  g.voxel_count = 20;
  return g;
}

Supervoxel riser(int i, int j, double x, double y, double z) {
  Supervoxel f;
  f.key = supervoxel_key({i, j, 0}, SurfaceClass::kFacade);
  f.center = {x, y, z};
  f.normal = {0, -1, 0};
  f.surface = SurfaceClass::kFacade;
  f.voxel_count = 20;
  return f;
}

Supervoxel flat(int i, int j, double x, double y, double z) {
  Supervoxel g;
  g.key = supervoxel_key({i, j, 0}, SurfaceClass::kGround);
  g.center = {x, y, z};
  g.surface = SurfaceClass::kGround;
  g.traversal_requirement = 1;
  g.voxel_count = 20;
  return g;
}

TEST(Slopes, PiecesOfOneFlightLieOnOneSlopeAndAStepBetweenFloorsDoesNot) {
  const Supervoxel low = flight_piece(0, 0, 3.0, 1.0), high = flight_piece(0, 2, 3.0, 2.7);
  EXPECT_TRUE(sloped(low));
  EXPECT_TRUE(on_one_slope(low, high, 1.75));
  EXPECT_TRUE(on_one_slope(high, low, 1.75));
  EXPECT_FALSE(on_one_slope(low, high, 1.5)) << "1.7 m apart in the plane";
  // Side by side across the flight: one plane too.
  EXPECT_TRUE(on_one_slope(low, flight_piece(1, 0, 3.6, 1.0), 1.75));
  // Flat floors a step apart are not a slope; a piece of a flight going the other way is not
  // on this one.
  EXPECT_FALSE(sloped(flat(0, 0, 0, 0, 0)));
  EXPECT_FALSE(on_one_slope(flat(0, 0, 0, 0, 0), flat(1, 0, 1, 0, 0.3), 1.75));
  Supervoxel down = high;
  down.normal.y() = -down.normal.y();
  EXPECT_FALSE(on_one_slope(low, down, 1.75));
  // A parallel slope 0.3 m above this one (a second flight over it) is not this one.
  Supervoxel above = high;
  above.center.z() += 0.3;
  EXPECT_FALSE(on_one_slope(low, above, 1.75));
}

TEST(Slopes, TheUphillSideOfAFlightIsTheOneItRisesTowards) {
  const Supervoxel piece = flight_piece(0, 0, 3.0, 1.0);  // rises along +y: side 2
  EXPECT_EQ(rim_side_direction(2), Eigen::Vector2d(0, 1));
  EXPECT_EQ(uphill_sides(piece, 0b1111), 1u << 2);
  EXPECT_EQ(uphill_sides(piece, 0b1011), 0u);
  EXPECT_EQ(uphill_sides(flat(0, 0, 0, 0, 0), 0b1111), 0u) << "flat ground has no uphill side";
}

// A riser lies on the flight's plane and faces downhill; a tread seen too steeply to be ground
// faces up: both are steps of the flight. A wall beside the flight faces across it, and a slab
// edge well above the plane is off it: those stay in a body's way.
TEST(Slopes, ARiserIsAStepOfItsFlightAndAWallBesideItIsNot) {
  const Supervoxel piece = flight_piece(0, 0, 3.0, 1.0);
  const double t = std::tan(kFlightDeg * M_PI / 180.0);
  const Supervoxel r = riser(0, 1, 3.0, 1.4, t * 1.4);
  EXPECT_TRUE(step_of_slope(piece.center, piece.normal, r.center, r.normal));
  EXPECT_TRUE(step_of_slope(piece.center, piece.normal, {3.3, 1.2, t * 1.2 + 0.05}, {0, -0.8, 0.6})) << "a steep tread";
  EXPECT_FALSE(step_of_slope(piece.center, piece.normal, {3.9, 1.2, t * 1.2 + 0.3}, {-1, 0, 0})) << "the side wall";
  EXPECT_FALSE(step_of_slope(piece.center, piece.normal, {3.0, 1.6, t * 1.6 + 0.7}, {0, -1, 0})) << "a slab edge over the flight";
  const Supervoxel floor = flat(0, 0, 3.0, 1.0, 0.0);
  EXPECT_FALSE(step_of_slope(floor.center, floor.normal, {3.0, 1.4, 0.1}, {0, -1, 0})) << "a kerb on flat ground is in the way";
}

HighLevelMap planning_map() {
  ClearanceOptions o;
  o.body_radius_m = {0.55, 0.6};
  return HighLevelMap({2, 1}, o);
}

// Foot (flat) - two pieces joined by a shared edge - a riser - the piece above, on the plane.
MapUpdate flight_seen_from_its_foot() {
  MapUpdate u;
  const Supervoxel foot = flat(0, -1, 3.0, 0.0, 0.0), a = flight_piece(0, 0, 3.0, 0.6), b = flight_piece(0, 1, 3.0, 1.3);
  const Supervoxel c = flight_piece(0, 3, 3.0, 2.9);
  u.upserts = {foot, a, b, c, riser(0, 2, 3.0, 2.1, std::tan(kFlightDeg * M_PI / 180.0) * 2.1)};
  u.edge_upserts = {EdgeKey::of(foot.key, a.key), EdgeKey::of(a.key, b.key)};
  return u;
}

uint64_t ground(int i, int j) { return supervoxel_key({i, j, 0}, SurfaceClass::kGround); }

TEST(Slopes, ARiserDoesNotPartAFlightOnThePlanningMap) {
  HighLevelMap map = planning_map();
  map.apply(flight_seen_from_its_foot());
  const TopologyGraph& g = map.graph();
  EXPECT_LT(g.dist(ground(0, -1), ground(0, 3), 0), TopologyGraph::kUnreachable);
  EXPECT_EQ(g.dist(ground(0, -1), ground(0, 3), 1), TopologyGraph::kUnreachable) << "the wheeled species may not use the flight";
  EXPECT_TRUE(map.edges().count(EdgeKey::of(ground(0, 1), ground(0, 3))) == 0) << "a bridge is not a shared edge";
  // The piece above goes: so does its bridge; it comes back: so does the bridge.
  MapUpdate gone;
  gone.removals = {ground(0, 3)};
  map.apply(gone);
  EXPECT_TRUE(g.neighbours(ground(0, 1)).size() == 1);
  map.apply(flight_seen_from_its_foot());
  EXPECT_LT(g.dist(ground(0, -1), ground(0, 3), 0), TopologyGraph::kUnreachable);
  // A shared edge over the bridge that comes and goes leaves the bridge.
  MapUpdate shared;
  shared.edge_upserts = {EdgeKey::of(ground(0, 1), ground(0, 3))};
  map.apply(shared);
  MapUpdate unshared;
  unshared.edge_removals = shared.edge_upserts;
  map.apply(unshared);
  EXPECT_LT(g.dist(ground(0, -1), ground(0, 3), 0), TopologyGraph::kUnreachable);
  // Without clearance options (hlmap's map) the graph is the shared edges only.
  HighLevelMap plain({2, 1});
  plain.apply(flight_seen_from_its_foot());
  EXPECT_EQ(plain.graph().dist(ground(0, -1), ground(0, 3), 0), TopologyGraph::kUnreachable);
}

TEST(Slopes, AWallUphillOfTheKnownFlightIsItsFrontierUntilGroundIsSeenBeyond) {
  HighLevelMap map = planning_map();
  MapUpdate u = flight_seen_from_its_foot();
  const double t = std::tan(kFlightDeg * M_PI / 180.0);
  u.upserts.push_back(riser(0, 4, 3.0, 3.4, t * 3.4));  // the next riser above the top piece
  map.apply(u);
  EXPECT_TRUE(map.frontier_sides(ground(0, 3)) & (1u << 2)) << "uphill, +y";
  EXPECT_FALSE(map.frontier_sides(ground(0, 1)) & (1u << 2)) << "ground on the plane beyond it";
  MapUpdate next;
  next.upserts = {flight_piece(0, 5, 3.0, 3.9)};
  map.apply(next);
  EXPECT_FALSE(map.frontier_sides(ground(0, 3)) & (1u << 2));
  // A wall beside flat ground is no frontier.
  HighLevelMap hall = planning_map();
  MapUpdate h;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) h.upserts.push_back(flat(i, j, i + 0.5, j + 0.5, 0.0));
  h.upserts.push_back(riser(1, 3, 1.5, 3.0, 0.5));
  hall.apply(h);
  EXPECT_EQ(hall.frontier_sides(ground(1, 2)) & (1u << 2), 0u);
}

}  // namespace
}  // namespace hexplore::highlevel
