// The angle part of J: the paper's limits, and the margin a team file may keep inside them.
#include "common/planning/visibility.h"

#include <gtest/gtest.h>

#include "common/core/team_config.h"

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

}  // namespace
}  // namespace hexplore::planning
