// The minimal view set over a whole route (route_pruning.h).
#include <gtest/gtest.h>

#include <set>

#include "common/planning/route_pruning.h"

namespace hexplore::planning {
namespace {

using highlevel::Facing;
using highlevel::SurfaceClass;
using highlevel::Supervoxel;

// A strip of ground y in [-12, 0) in front of a wall facing -y at y = 0.5, x in [0, 10),
// z in [1, 6); every wall supervoxel is an ISE.
struct WallScene {
  highlevel::HighLevelMap map{{1, 2}};
  std::vector<uint64_t> wall;
  WallScene() {
    highlevel::MapUpdate up;
    up.full_snapshot = true;
    for (int x = 0; x < 10; ++x)
      for (int y = -12; y < 0; ++y) {
        Supervoxel g;
        g.center = {x + 0.5, y + 0.5, 0.0};
        g.surface = SurfaceClass::kGround;
        g.traversal_requirement = 1;
        g.covered = true;
        g.key = highlevel::supervoxel_key({x, y, 0}, g.surface);
        up.upserts.push_back(g);
      }
    for (int x = 0; x < 10; ++x)
      for (int z = 1; z < 6; ++z) {
        Supervoxel f;
        f.center = {x + 0.5, 0.5, z + 0.5};
        f.normal = -Eigen::Vector3d::UnitY();
        f.surface = SurfaceClass::kFacade;
        f.key = highlevel::supervoxel_key({x, 0, z}, f.surface, Facing::kMinusY);
        up.upserts.push_back(f);
        wall.push_back(f.key);
      }
    map.apply(up);
  }
  TaskView view_at(int x, int y, uint64_t target) const {
    TaskView v;
    v.ground_key = highlevel::supervoxel_key({x, y, 0}, SurfaceClass::kGround);
    v.key = target;
    v.position = {x + 0.5, y + 0.5, 0.0};
    v.look_at = map.find(target)->center;
    v.facade = true;
    v.targets = {target};
    return v;
  }
};

SpeciesCapability long_range() {
  SpeciesCapability s;
  s.observation_range_m = 27.0;
  return s;
}

TEST(RoutePruning, OneStopThatSeesTheWholeWallReplacesAStopPerTarget) {
  WallScene scene;
  PlannerOptions o;
  const MapContext ctx(scene.map, o);
  // One view per target, in a row 8 m in front of the wall (as clusters of 5 m would make them).
  std::vector<TaskView> route;
  for (size_t i = 0; i < scene.wall.size(); ++i) route.push_back(scene.view_at(int(i % 10), -8, scene.wall[i]));
  RoutePruneStats st;
  const std::vector<TaskView> pruned = prune_route(ctx, route, long_range(), o, &st);
  EXPECT_EQ(st.views_before, 50);
  EXPECT_LT(pruned.size(), 5u) << "a few stops see the whole 10 m x 5 m wall from 8 m";
  std::set<uint64_t> held;
  for (const TaskView& v : pruned) held.insert(v.targets.begin(), v.targets.end());
  EXPECT_EQ(held, std::set<uint64_t>(scene.wall.begin(), scene.wall.end())) << "every target stays with a view";
  // Kept views keep their route order.
  for (size_t i = 1; i < pruned.size(); ++i) {
    const auto before = [&](const TaskView& v) {
      return std::find_if(route.begin(), route.end(), [&](const TaskView& r) { return r.key == v.key; }) - route.begin();
    };
    EXPECT_LT(before(pruned[i - 1]), before(pruned[i]));
  }
}

TEST(RoutePruning, AViewNobodyElseCanReplaceStays) {
  WallScene scene;
  PlannerOptions o;
  const MapContext ctx(scene.map, o);
  // A view 2 m in front of the wall's low west end, and one 12 m off its high east end: with a
  // 10 m range neither sees the other's target, so both stay.
  std::vector<TaskView> route = {scene.view_at(0, -2, scene.wall[0]), scene.view_at(9, -11, scene.wall[49])};
  SpeciesCapability short_range;
  short_range.observation_range_m = 10.0;
  const std::vector<TaskView> pruned = prune_route(ctx, route, short_range, o);
  ASSERT_EQ(pruned.size(), 2u);
  EXPECT_EQ(pruned[0].targets, std::vector<uint64_t>{scene.wall[0]});
  EXPECT_EQ(pruned[1].targets, std::vector<uint64_t>{scene.wall[49]});
}

TEST(RoutePruning, TheStopThatSeesMoreKeepsTheTargets) {
  WallScene scene;
  PlannerOptions o;
  const MapContext ctx(scene.map, o);
  // A stop 1 m from the wall for its top row (z = 5.5, seen at about 79 deg of elevation, out
  // of J) and one 10 m off for its bottom row, which sees the top row at about 27 deg too.
  std::vector<TaskView> route = {scene.view_at(5, -1, scene.wall[5 * 5 + 4]), scene.view_at(5, -10, scene.wall[5 * 5 + 0])};
  const std::vector<TaskView> pruned = prune_route(ctx, route, long_range(), o);
  ASSERT_EQ(pruned.size(), 1u);
  EXPECT_EQ(pruned[0].position.y(), -9.5);
  EXPECT_EQ(std::set<uint64_t>(pruned[0].targets.begin(), pruned[0].targets.end()),
            (std::set<uint64_t>{scene.wall[5 * 5 + 4], scene.wall[5 * 5 + 0]}));
}

}  // namespace
}  // namespace hexplore::planning
