#include "common/highlevel/clearance.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "common/highlevel/high_level_map.h"

namespace hexplore::highlevel {
namespace {

// A hall along +x between two walls (y = 0 and y = width): ground supervoxels centred every
// metre (rows at y = y0, y0 + 1, ...), wall facades every metre at body height, edges between
// 8-neighbours. One species, body radius `radius`.
MapUpdate hall(double width, double y0, int rows, int length = 10) {
  MapUpdate u;
  auto ground_key = [](int i, int j) { return supervoxel_key({i, j, 0}, SurfaceClass::kGround); };
  for (int i = 0; i < length; ++i)
    for (int j = 0; j < rows; ++j) {
      Supervoxel g;
      g.key = ground_key(i, j);
      g.center = {i + 0.5, y0 + j, 0.0};
      g.surface = SurfaceClass::kGround;
      g.traversal_requirement = 1;
      g.voxel_count = 40;
      u.upserts.push_back(g);
      for (int di = 0; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          if ((di == 0 && dj <= 0) || i + di >= length || j + dj < 0 || j + dj >= rows) continue;
          u.edge_upserts.push_back(EdgeKey::of(g.key, ground_key(i + di, j + dj)));
        }
    }
  for (int i = 0; i < length; ++i)
    for (int side = 0; side < 2; ++side) {
      Supervoxel f;
      f.key = supervoxel_key({i, side == 0 ? -1 : 100, 0}, SurfaceClass::kFacade);
      f.center = {i + 0.5, side == 0 ? 0.0 : width, 0.5};
      f.normal = {0.0, side == 0 ? 1.0 : -1.0, 0.0};
      f.surface = SurfaceClass::kFacade;
      f.voxel_count = 40;
      u.upserts.push_back(f);
    }
  return u;
}

double wall_distance(const Eigen::Vector3d& p, double width) { return std::min(p.y(), width - p.y()); }

// The hall's ground without its walls: open ground whose edges are the rim of the known ground.
MapUpdate open_ground(double y0, int rows, int length = 10) {
  MapUpdate u = hall(1.0, y0, rows, length);
  std::erase_if(u.upserts, [](const Supervoxel& s) { return s.facade(); });
  return u;
}

TEST(Clearance, IndexMeasuresTheDistanceToWallPatchesAtBodyHeight) {
  ClearanceOptions o;
  o.body_radius_m = {0.6};
  ClearanceIndex index(o);
  Supervoxel wall;
  wall.key = 1 | kFacadeKeyBit;
  wall.center = {0.5, 0.0, 0.5};
  wall.normal = {0, 1, 0};
  wall.surface = SurfaceClass::kFacade;
  index.insert(wall);
  EXPECT_NEAR(index.clearance({0.5, 0.4, 0.0}, 2.0), 0.4, 1e-9);
  EXPECT_NEAR(index.clearance({0.8, 0.4, 0.0}, 2.0), 0.4, 1e-9);  // along the wall patch
  EXPECT_NEAR(index.clearance({1.5, 0.0, 0.0}, 2.0), 0.5, 1e-9);  // past its end
  EXPECT_NEAR(index.clearance({0.5, 0.4, 3.5}, 2.0), 2.0, 1e-9);  // a floor up: not in the way
  const Eigen::Vector3d moved = index.clear_position({0.5, 0.4, 0.0}, 0.6);
  EXPECT_NEAR(moved.y(), 0.6, 1e-6);
  EXPECT_NEAR(moved.x(), 0.5, 1e-6);
  index.erase(wall);
  EXPECT_NEAR(index.clearance({0.5, 0.4, 0.0}, 2.0), 2.0, 1e-9);
}

// With body radii, paths along a hall keep off the walls where the hall has room: the
// shortest path along the row next to the wall (0.5 m off it) loses to the row inside.
TEST(Clearance, PathsInAWideHallKeepTheBodyRadiusFromTheWalls) {
  ClearanceOptions o;
  o.body_radius_m = {0.6};
  HighLevelMap map({1}, o);
  map.apply(hall(4.0, 0.5, 4));
  const TopologyGraph& g = map.graph();
  const uint64_t a = supervoxel_key({0, 0, 0}, SurfaceClass::kGround);
  const uint64_t b = supervoxel_key({9, 0, 0}, SurfaceClass::kGround);
  EXPECT_NEAR(g.clearance(a), 0.5, 1e-9);
  EXPECT_GE(g.clearance(supervoxel_key({5, 1, 0}, SurfaceClass::kGround)), 0.6);  // measured up to radius + 0.25
  const auto keys = g.path(a, b, 0);
  ASSERT_FALSE(keys.empty());
  for (uint64_t k : keys) EXPECT_GE(wall_distance(*g.waypoint(k, 0), 4.0), 0.6 - 1e-6) << k;
  // Without radii (the hlmap service's map) nothing changes: exact shortest paths along the wall.
  HighLevelMap plain({1});
  plain.apply(hall(4.0, 0.5, 4));
  EXPECT_NEAR(plain.graph().dist(a, b, 0), 9.0, 1e-9);
  EXPECT_EQ(*plain.graph().waypoint(a, 0), *plain.graph().position(a));
}

// A corridor 1.2 m wide whose ground supervoxels are centred off its middle (0.35 m from one
// wall): it stays passable, and the waypoints move to the middle, where the body fits best.
TEST(Clearance, NarrowCorridorStaysPassableWithWaypointsInTheMiddle) {
  ClearanceOptions o;
  o.body_radius_m = {0.61};
  HighLevelMap map({1}, o);
  map.apply(hall(1.2, 0.35, 1));
  const TopologyGraph& g = map.graph();
  const uint64_t a = supervoxel_key({0, 0, 0}, SurfaceClass::kGround);
  const uint64_t b = supervoxel_key({9, 0, 0}, SurfaceClass::kGround);
  const auto keys = g.path(a, b, 0);
  ASSERT_EQ(keys.size(), 10u);
  for (uint64_t k : keys) EXPECT_NEAR(g.waypoint(k, 0)->y(), 0.6, 0.02);
}

// Clearance follows the map: a wall that appears later moves the waypoints near it, and
// one that goes frees them again.
TEST(Clearance, UpdatesFollowFacadesAddedAndRemoved) {
  ClearanceOptions o;
  o.body_radius_m = {0.6};
  HighLevelMap map({1}, o);
  // Open ground on both sides of where the wall will stand (else its edge is a rim, below).
  map.apply(open_ground(-2.5, 7));
  const uint64_t a = supervoxel_key({3, 3, 0}, SurfaceClass::kGround);  // centred at y = 0.5
  EXPECT_GT(map.graph().clearance(a), 0.6);
  MapUpdate wall;
  Supervoxel f;
  f.key = supervoxel_key({3, -1, 0}, SurfaceClass::kFacade);
  f.center = {3.5, 0.0, 0.5};
  f.normal = {0, 1, 0};
  f.surface = SurfaceClass::kFacade;
  wall.upserts.push_back(f);
  map.apply(wall);
  EXPECT_NEAR(map.graph().clearance(a), 0.5, 1e-9);
  EXPECT_NEAR(map.graph().waypoint(a, 0)->y(), 0.6, 1e-6);
  MapUpdate gone;
  gone.removals.push_back(f.key);
  map.apply(gone);
  EXPECT_GT(map.graph().clearance(a), 0.6);
  EXPECT_NEAR(map.graph().waypoint(a, 0)->y(), 0.5, 1e-9);
}

// Ground under something low (a vehicle roof 1.2 m up, seen from outside; its underside is
// not in the map) has no room for a body to stand; open ground has.
TEST(Clearance, NoRoomToStandUnderAnOverhang) {
  ClearanceOptions o;
  o.body_radius_m = {0.54};
  o.body_half_width_m = {0.3};
  HighLevelMap map({1}, o);
  MapUpdate u = hall(4.0, 0.5, 4);
  Supervoxel roof;
  roof.key = supervoxel_key({5, 2, 1}, SurfaceClass::kFacade);
  roof.center = {5.5, 2.5, 1.2};
  roof.normal = {0, 0, 1};
  roof.surface = SurfaceClass::kFacade;
  u.upserts.push_back(roof);
  map.apply(u);
  EXPECT_FALSE(map.graph().room_to_stand(supervoxel_key({5, 2, 0}, SurfaceClass::kGround), 0));
  EXPECT_TRUE(map.graph().room_to_stand(supervoxel_key({2, 2, 0}, SurfaceClass::kGround), 0));
  // Paths may still pass it (the estimate is coarse; a door must not close), at a cost.
  EXPECT_TRUE(map.graph().passable(supervoxel_key({5, 2, 0}, SurfaceClass::kGround), 0));
  EXPECT_GT(map.graph().clearance_penalty(supervoxel_key({5, 2, 0}, SurfaceClass::kGround), 0), 0.0);
}

// A slab facing down 0.8 m over the hall's middle: over ground both species may use it is in
// the MR1000-sized body's way (0.8 m tall); over ground only the 0.4 m tall tracked species may
// use (a flight), it is a ceiling with room under it. B1's flight of the multi-building scene
// had such a slab beside its upper treads, and no tracked robot had room to stand there.
TEST(Clearance, ACeilingOverEveryBodyThatMayStandThereLeavesRoom) {
  ClearanceOptions o;
  o.body_radius_m = {0.54, 0.61};
  o.body_half_width_m = {0.3, 0.35};
  o.body_height_m = {0.4, 0.8};  // tracked (level 2), wheeled (level 1)
  o.species_level = {2, 1};
  EXPECT_NEAR(o.overhead_m(2), 0.6, 1e-9);
  EXPECT_NEAR(o.overhead_m(1), 1.0, 1e-9);
  for (int requirement : {1, 2}) {
    HighLevelMap map({2, 1}, o);
    MapUpdate u = hall(4.0, 0.5, 4);
    for (auto& sv : u.upserts) sv.traversal_requirement = requirement;
    Supervoxel slab;
    slab.key = supervoxel_key({5, 2, 1}, SurfaceClass::kFacade);
    slab.center = {5.5, 2.5, 0.8};
    slab.normal = {0, 0, -1};
    slab.surface = SurfaceClass::kFacade;
    u.upserts.push_back(slab);
    map.apply(u);
    EXPECT_EQ(map.graph().room_to_stand(supervoxel_key({5, 2, 0}, SurfaceClass::kGround), 0), requirement == 2)
        << "ground of requirement " << requirement;
  }
}

// A one-voxel sliver of ground beyond the known ground's edge (a slab edge grazed from below a
// flight's top) holds no body and says nothing of what lies beyond: the edge stays open.
// Ground of a few voxels there closes it.
TEST(Clearance, ASliverOfGroundClosesNoSide) {
  for (int voxels : {1, 5}) {
    ClearanceOptions o;
    o.body_radius_m = {0.61};
    HighLevelMap map({1}, o);
    MapUpdate u = open_ground(0.5, 3, 3);  // x 0.5..2.5
    Supervoxel beyond;
    beyond.key = supervoxel_key({3, 1, 0}, SurfaceClass::kGround);
    beyond.center = {3.5, 1.5, 0.1};
    beyond.surface = SurfaceClass::kGround;
    beyond.traversal_requirement = 1;
    beyond.voxel_count = voxels;
    u.upserts.push_back(beyond);
    map.apply(u);
    const bool open = map.frontier_sides(supervoxel_key({2, 1, 0}, SurfaceClass::kGround)) & (1u << 0);  // +x
    EXPECT_EQ(open, voxels == 1) << voxels << " voxels beyond the edge";
  }
}

// The edge of the known ground keeps a body off like a wall: a vertex on the last row is half
// a seed interval from the rim, its waypoint moves in until the body's radius fits (it can
// turn there), a corner's moves in both ways, and rows inside are untouched. The MR1000 of
// the single-building scene drove along the edge of the ground plane and could not turn.
TEST(Clearance, TheRimOfTheKnownGroundKeepsBodiesOffLikeAWall) {
  ClearanceOptions o;
  o.body_radius_m = {0.61};
  o.body_half_width_m = {0.35};
  HighLevelMap map({1}, o);
  map.apply(open_ground(0.5, 6));
  const TopologyGraph& g = map.graph();
  const uint64_t edge = supervoxel_key({5, 0, 0}, SurfaceClass::kGround);    // (5.5, 0.5)
  const uint64_t corner = supervoxel_key({0, 0, 0}, SurfaceClass::kGround);  // (0.5, 0.5)
  const uint64_t inside = supervoxel_key({5, 2, 0}, SurfaceClass::kGround);  // (5.5, 2.5)
  EXPECT_NEAR(g.clearance(edge), 0.5, 1e-9);
  EXPECT_NEAR(g.waypoint(edge, 0)->y(), 0.61, 1e-6);
  EXPECT_NEAR(g.waypoint(edge, 0)->x(), 5.5, 1e-6);
  EXPECT_GT(g.waypoint(corner, 0)->x(), 0.6);
  EXPECT_GT(g.waypoint(corner, 0)->y(), 0.6);
  EXPECT_GE(g.clearance(inside), 0.61);
  EXPECT_EQ(*g.waypoint(inside, 0), *g.position(inside));
  // The body still stands on the last row (it is wider than half a body), at a cost to enter.
  EXPECT_TRUE(g.room_to_stand(edge, 0));
  EXPECT_GT(g.clearance_penalty(edge, 0), 0.0);
  EXPECT_EQ(g.clearance_penalty(inside, 0), 0.0);
  // The map says which sides are open (bit i: rim_side_direction(i); -y is side 3, -x side 1).
  EXPECT_EQ(map.frontier_sides(edge), 1u << 3);
  EXPECT_EQ(map.frontier_sides(corner), (1u << 1) | (1u << 3));
  EXPECT_EQ(map.frontier_sides(inside), 0u);
  EXPECT_EQ(rim_side_direction(3), Eigen::Vector2d(0, -1));
}

// Along a wall the rim is not counted twice: the hall's rows next to its walls move as far as
// the walls alone push them.
TEST(Clearance, AWallAtTheEdgeOfTheGroundIsNotARimAsWell) {
  ClearanceOptions o;
  o.body_radius_m = {0.61};
  HighLevelMap map({1}, o);
  map.apply(hall(4.0, 0.5, 4));
  const uint64_t by_wall = supervoxel_key({5, 0, 0}, SurfaceClass::kGround);
  EXPECT_EQ(map.frontier_sides(by_wall), 0u);
  EXPECT_NEAR(map.graph().clearance(by_wall), 0.5, 1e-9);
  EXPECT_NEAR(map.graph().waypoint(by_wall, 0)->y(), 0.61, 1e-6);
  EXPECT_NEAR(map.graph().waypoint(by_wall, 0)->x(), 5.5, 1e-6);
}

// The rim follows the map: ground seen beyond it moves it out (the old edge row is inside
// now), and ground that goes brings it back.
TEST(Clearance, GroundSeenBeyondTheRimMovesIt) {
  ClearanceOptions o;
  o.body_radius_m = {0.61};
  HighLevelMap map({1}, o);
  map.apply(open_ground(0.5, 4));
  const uint64_t old_edge = supervoxel_key({5, 0, 0}, SurfaceClass::kGround);
  EXPECT_NEAR(map.graph().clearance(old_edge), 0.5, 1e-9);
  MapUpdate more = open_ground(-0.5, 1);
  for (Supervoxel& s : more.upserts) s.key = supervoxel_key({int(std::floor(s.center.x())), -1, 0}, SurfaceClass::kGround);
  more.edge_upserts.clear();
  EXPECT_NE(map.frontier_sides(old_edge), 0u);
  map.apply(more);
  EXPECT_EQ(map.frontier_sides(old_edge), 0u);
  EXPECT_GE(map.graph().clearance(old_edge), 0.61);
  EXPECT_EQ(*map.graph().waypoint(old_edge, 0), *map.graph().position(old_edge));
  MapUpdate gone;
  for (const Supervoxel& s : more.upserts) gone.removals.push_back(s.key);
  map.apply(gone);
  EXPECT_NE(map.frontier_sides(old_edge), 0u);
  EXPECT_NEAR(map.graph().clearance(old_edge), 0.5, 1e-9);
  EXPECT_NEAR(map.graph().waypoint(old_edge, 0)->y(), 0.61, 1e-6);
}

// Clearance depends only on the map, not on the order its pieces came in: ground and walls
// that arrive, move and go in random batches leave every vertex with the clearance and the
// waypoint that one update of the final map gives (the rim of a vertex changes when ground up
// to two seed intervals from it does, and that rim reaches bodies around it), and with the
// same graph: the field's last columns are a slope, whose pieces bridges join (slopes.h).
class ClearanceOrder : public ::testing::TestWithParam<int> {};

TEST_P(ClearanceOrder, TheSameMapGivesTheSameClearanceWhateverTheOrderOfUpdates) {
  ClearanceOptions o;
  o.body_radius_m = {0.61, 0.54};
  o.body_half_width_m = {0.35, 0.3};
  std::mt19937 rng(GetParam());
  // A patchy field: ground cells of a 12 x 12 grid present at random, with jittered centres,
  // and a few wall pieces; from x = 8 on, the ground rises 30 deg along +x.
  std::vector<Supervoxel> all;
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      if (rng() % 4 == 0) continue;
      Supervoxel g;
      g.key = supervoxel_key({i, j, 0}, SurfaceClass::kGround);
      g.center = {i + 0.5 + jitter(rng), j + 0.5 + jitter(rng), 0.0};
      if (i >= 8) {
        g.center.z() = std::tan(M_PI / 6) * (g.center.x() - 8.0);
        g.normal = Eigen::Vector3d(-std::sin(M_PI / 6), 0, std::cos(M_PI / 6));
      }
      g.surface = SurfaceClass::kGround;
      g.traversal_requirement = 1;
      all.push_back(g);
    }
  for (int w = 0; w < 6; ++w) {
    Supervoxel f;
    f.key = supervoxel_key({int(rng() % 12), int(rng() % 12), 0}, SurfaceClass::kFacade);
    f.center = {seed_cell_of(f.key).x + 0.5, seed_cell_of(f.key).y + 0.5, 0.6};
    f.normal = w % 2 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 1, 0);
    f.surface = SurfaceClass::kFacade;
    all.push_back(f);
  }
  auto with_edges = [](std::vector<Supervoxel> svs) {
    MapUpdate u;
    u.upserts = std::move(svs);
    for (const Supervoxel& a : u.upserts)
      for (const Supervoxel& b : u.upserts)
        if (a.ground() && b.ground() && a.key < b.key && (a.center - b.center).norm() < 1.6)
          u.edge_upserts.push_back(EdgeKey::of(a.key, b.key));
    return u;
  };
  HighLevelMap once({1, 1}, o);
  once.apply(with_edges(all));

  // The same map reached through batches: everything in random order, a third of it first at
  // another place, some pieces removed, and at last only what still differs, in small batches
  // (a vertex is re-measured only when something near it changes, so this tests that reach).
  HighLevelMap batches({1, 1}, o);
  std::map<uint64_t, Supervoxel> applied;
  auto apply = [&](std::vector<Supervoxel> up, std::vector<uint64_t> removed) {
    MapUpdate u = with_edges(up);
    // Edges to pieces applied before, so the graph is the same at the end.
    for (const Supervoxel& a : up)
      for (const auto& [k, b] : applied)
        if (a.ground() && b.ground() && a.key != k && (a.center - b.center).norm() < 1.6)
          u.edge_upserts.push_back(EdgeKey::of(a.key, k));
    u.removals = removed;
    batches.apply(u);
    for (uint64_t k : removed) applied.erase(k);
    for (const Supervoxel& a : up) applied[a.key] = a;
  };
  std::vector<Supervoxel> order = all;
  std::shuffle(order.begin(), order.end(), rng);
  for (size_t at = 0; at < order.size(); at += 9) {
    std::vector<Supervoxel> batch(order.begin() + at, order.begin() + std::min(order.size(), at + 9));
    for (Supervoxel& s : batch)
      if (rng() % 3 == 0) s.center.x() += 0.4;  // first seen a little elsewhere
    apply(batch, {});
  }
  for (size_t at = 0; at < order.size(); at += 13) {
    std::vector<uint64_t> gone;
    for (size_t k = at; k < std::min(order.size(), at + 4); ++k) gone.push_back(order[k].key);
    apply({}, gone);
  }
  std::vector<Supervoxel> differs;
  for (const Supervoxel& s : order)
    if (!applied.count(s.key) || applied[s.key].center != s.center) differs.push_back(s);
  ASSERT_GT(differs.size(), 20u);
  for (size_t at = 0; at < differs.size(); at += 3)
    apply(std::vector<Supervoxel>(differs.begin() + at, differs.begin() + std::min(differs.size(), at + 3)), {});
  // Shared edges made while a piece stood elsewhere go as well: the same map has the same edges.
  MapUpdate stale;
  for (const EdgeKey& e : batches.edges())
    if (!once.edges().count(e)) stale.edge_removals.push_back(e);
  batches.apply(stale);

  int bridges = 0;
  for (uint64_t key : once.graph().vertex_keys())
    for (const auto& [other, length] : once.graph().neighbours(key)) bridges += once.edges().count(EdgeKey::of(key, other)) ? 0 : 1;
  EXPECT_GT(bridges, 0) << "the slope's pieces need a bridge somewhere";
  for (uint64_t key : once.graph().vertex_keys()) {
    ASSERT_TRUE(batches.graph().contains(key));
    EXPECT_NEAR(batches.graph().clearance(key), once.graph().clearance(key), 1e-9) << seed_cell_of(key).x << "," << seed_cell_of(key).y;
    for (int species = 0; species < 2; ++species)
      EXPECT_LT((*batches.graph().waypoint(key, species) - *once.graph().waypoint(key, species)).norm(), 1e-9);
    EXPECT_EQ(batches.frontier_sides(key), once.frontier_sides(key)) << seed_cell_of(key).x << "," << seed_cell_of(key).y;
    auto sorted = [](std::vector<std::pair<uint64_t, double>> v) {
      std::sort(v.begin(), v.end());
      return v;
    };
    const auto expected = sorted(once.graph().neighbours(key)), got = sorted(batches.graph().neighbours(key));
    ASSERT_EQ(got.size(), expected.size()) << seed_cell_of(key).x << "," << seed_cell_of(key).y;
    for (size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].first, expected[k].first);
      EXPECT_NEAR(got[k].second, expected[k].second, 1e-9);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Clearance, ClearanceOrder, ::testing::Range(1, 31));

}  // namespace
}  // namespace hexplore::highlevel
