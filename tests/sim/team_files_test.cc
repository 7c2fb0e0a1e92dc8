// Every team file shipped in deploy/teams: it loads, its world loads (built-in or a mesh
// beside the checkout, placed by its scene_import), every robot stands at its start on the
// ground (z = 0) inside the exploration region, and drives a metre straight ahead from there.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/sim/ray_caster.h"
#include "common/sim/robot_motion.h"
#include "common/sim/scene_error.h"
#include "common/sim/scenes.h"

namespace hexplore::sim {
namespace {

TEST(TeamFiles, EveryRobotStartsOnOpenGroundInsideItsRegion) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(HEXPLORE_SOURCE_DIR) + "/deploy/teams")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const auto team = core::load_team_config(entry.path().string());
    const std::string scene_path = resolve_scene(team.scene, team.source_file);
    if (!is_builtin_scene(team.scene) && !std::filesystem::exists(scene_path)) {
      // Third-party meshes live in the shared folder beside the checkout; without it there is
      // nothing to check, with it a missing file is a broken path in the team file.
      if (std::filesystem::exists(HEXPLORE_SHARED_DIR))
        ADD_FAILURE() << entry.path() << ": scene " << team.scene << " not found (resolved to " << scene_path << ")";
      continue;
    }
    const SceneInfo scene = load_team_scene(team);
    const RayCaster caster(scene.mesh);
    for (const auto& r : team.robots) {
      const std::string what = entry.path().filename().string() + " " + r.id;
      EXPECT_TRUE(team.exploration_region.contains(r.start_position_m)) << what;
      const double yaw = r.start_yaw_deg * M_PI / 180.0;
      RobotMotion robot(caster, *team.find_species(r.species), r.start_position_m, yaw);
      EXPECT_NEAR(robot.ground_position().z(), 0.0, 0.02) << what;
      robot.follow({r.start_position_m + Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0.0)});
      for (int i = 0; i < 100 && robot.state() == MotionState::kMoving; ++i) robot.step(0.1);
      EXPECT_EQ(robot.state(), MotionState::kIdle) << what << ": " << to_string(robot.block_reason());
    }
  }
  EXPECT_GE(files, 5);
}

}  // namespace
}  // namespace hexplore::sim
