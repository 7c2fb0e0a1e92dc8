// The angle part of J: the paper's limits, and the margin a team file may keep inside them;
// the line of sight of J through the facade supervoxels (OcclusionGrid).
#include "common/planning/visibility.h"

#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/highlevel/high_level_map.h"

namespace hexplore::planning {
namespace {

// A sensor 1 m above the ground looking at a wall patch (normal -y) whose centre is seen at
// `incidence_deg` from the normal in the horizontal plane, 15 m away, level with the sensor.
ViewGeometry level_view(double incidence_deg) {
  const double a = incidence_deg * kDegToRad;
  const Eigen::Vector3d target(0, 10, 1);
  const Eigen::Vector3d sensor = target + 15.0 * Eigen::Vector3d(std::sin(a), -std::cos(a), 0);
  return view_geometry(sensor, Eigen::Vector3d::UnitZ(), target, -Eigen::Vector3d::UnitY());
}

TEST(AnglesOk, TheMarginNarrowsBothAngleLimits) {
  const PlannerOptions o;  // gamma_th 45, theta [-45, 45]
  double margin = 0.0;
  EXPECT_TRUE(angles_ok(level_view(40.0), o, margin));
  EXPECT_FALSE(angles_ok(level_view(46.0), o, margin));
  margin = 15.0;
  EXPECT_FALSE(angles_ok(level_view(40.0), o, margin));
  EXPECT_TRUE(angles_ok(level_view(25.0), o, margin));
  // Elevation: a target 35 deg above the sensor, facing it, passes 45 but not 45 - 15.
  const Eigen::Vector3d target(0, 10, 1.0 + 10.0 * std::tan(35.0 * kDegToRad));
  const ViewGeometry up =
      view_geometry({0, 0, 1}, Eigen::Vector3d::UnitZ(), target, Eigen::Vector3d(0, -1, -std::tan(35.0 * kDegToRad)).normalized());
  EXPECT_FALSE(angles_ok(up, o, margin));
  margin = 0.0;
  EXPECT_TRUE(angles_ok(up, o, margin));
}

TEST(AnglesOk, AMarginThatLeavesNoRoomIsAConfigError) {
  const std::string team = R"(
species:
  - builtin: SLUGCAT
robots:
  - id: r1
    species: SLUGCAT
    start: [0, 0, 0]
params:
  shared_view_angle_margin_deg: )";
  EXPECT_NO_THROW(core::parse_team_config(team + "15", "margin 15"));
  EXPECT_THROW(core::parse_team_config(team + "45", "margin 45"), std::exception);
  EXPECT_THROW(core::parse_team_config(team + "-1", "margin -1"), std::exception);
}

// A map of facade supervoxels, keyed as the segmentation keys them.
struct FacadeMap {
  highlevel::HighLevelMap map{std::vector<int>{1}};
  highlevel::MapUpdate update;
  highlevel::Supervoxel add(const Eigen::Vector3d& center, const Eigen::Vector3d& normal) {
    highlevel::Supervoxel sv;
    sv.center = center;
    sv.normal = normal;
    sv.surface = highlevel::SurfaceClass::kFacade;
    sv.voxel_count = 30;
    sv.key = highlevel::supervoxel_key(core::cell_of(center, 1.0), sv.surface, highlevel::facing_of(normal.cast<float>()));
    update.upserts.push_back(sv);
    return sv;
  }
  // A wall along x in [x0, x1] at y, 0.2 m thick, 3 m high: an outer face (normal -y) at y and
  // an inner one (+y) 0.2 m behind it, one supervoxel per metre of each.
  std::vector<highlevel::Supervoxel> wall(int x0, int x1, double y) {
    std::vector<highlevel::Supervoxel> inner;
    for (int x = x0; x < x1; ++x)
      for (int z = 0; z < 3; ++z) {
        add({x + 0.5, y, z + 0.5}, -Eigen::Vector3d::UnitY());
        inner.push_back(add({x + 0.5, y + 0.2, z + 0.5}, Eigen::Vector3d::UnitY()));
      }
    return inner;
  }
  OcclusionGrid grid() {
    map.apply(update);
    return OcclusionGrid(map, 1.0);
  }
};

// Cells spared the last metre before the target: the inside face of a wall, 0.2 m behind its
// outside face, was "seen" from outside through the wall, and the MR1000 went to look at it.
TEST(OcclusionGrid, AWallHidesItsInsideFaceFromOutside) {
  FacadeMap m;
  const auto inner = m.wall(0, 10, 5.0);
  const OcclusionGrid grid = m.grid();
  const Eigen::Vector3d outside(5.0, -5.0, 1.0), inside(5.0, 12.0, 1.0);
  const highlevel::Supervoxel& target = inner[3 * 5 + 1];  // x = 5.5, z = 1.5
  EXPECT_FALSE(grid.clear(outside, target));
  EXPECT_TRUE(grid.clear(inside, target));
}

// A surface's supervoxels are not coplanar (voxel noise, a corner's overlap): its own
// neighbours in front of the target do not hide it, a wall of another facing does.
TEST(OcclusionGrid, ATargetsOwnSurfaceDoesNotHideItButAnotherSurfaceInFrontDoes) {
  const Eigen::Vector3d sensor(-6.0, 0.0, 1.5);  // well off to the side: the ray grazes the wall
  FacadeMap m;
  const highlevel::Supervoxel target = m.add({5.5, 5.0, 1.5}, -Eigen::Vector3d::UnitY());
  m.add({4.5, 4.8, 1.5}, Eigen::Vector3d(0.3, -1.0, 0.0).normalized());  // a neighbour, 0.2 m proud
  EXPECT_TRUE(m.grid().clear(sensor, target));

  // A pillar's side (facing +x) across the ray 0.8 m before the target.
  FacadeMap other;
  const highlevel::Supervoxel same = other.add({5.5, 5.0, 1.5}, -Eigen::Vector3d::UnitY());
  other.add(same.center - 0.8 * (same.center - sensor).normalized(), Eigen::Vector3d::UnitX());
  EXPECT_FALSE(other.grid().clear(sensor, same));
}

// Between the plates of a wall there is no gap a ray slips through, and a ray that passes
// beside the wall's end is clear.
TEST(OcclusionGrid, AWallIsClosedAndEndsWhereItsSupervoxelsEnd) {
  FacadeMap m;
  m.wall(0, 10, 5.0);
  const highlevel::Supervoxel target = m.add({5.0, 10.0, 1.0}, -Eigen::Vector3d::UnitY());
  const OcclusionGrid grid = m.grid();
  for (double x = 0.25; x < 10.0; x += 0.1)
    EXPECT_FALSE(grid.clear({x, 0.0, 1.0}, target)) << "through the wall at x = " << x;
  EXPECT_TRUE(grid.clear({20.0, 0.0, 1.0}, target));  // crosses y = 5 at x = 12.5, past the wall's end
}

}  // namespace
}  // namespace hexplore::planning
