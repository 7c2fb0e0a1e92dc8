#pragma once
// A four-robot, two-species team on a small synthetic map for planner tests: 30 x 20 m, one
// building, and a rubble band that cuts off the east end (x >= 26) for the wheeled species.

#include <memory>
#include <string>

#include "common/core/team_config.h"
#include "common/planning/planner_registry.h"

#include "tests/support/planning_scene.h"

namespace hexplore::planning::testing {

inline core::TeamConfig four_robot_team() {
  core::TeamConfig team;
  team.species = {core::builtin_slugcat(), core::builtin_mr1000()};
  team.robots = {{"slug1", "SLUGCAT", {1.5, 1.5, 0}, 0},
                 {"slug2", "SLUGCAT", {28.5, 18.5, 0}, 0},
                 {"mr1", "MR1000", {1.5, 18.5, 0}, 0},
                 {"mr2", "MR1000", {20.5, 1.5, 0}, 0}};
  return team;
}

inline SyntheticSceneOptions rubble_band_scene() {
  SyntheticSceneOptions o;
  o.width_cells = 30;
  o.depth_cells = 20;
  o.buildings = {{5, 5, 14, 13, 5}};
  o.rubble = {Eigen::Vector4i(24, 0, 25, 19)};
  o.covered_fraction = 0.3;
  return o;
}

struct PlannerFixture {
  core::TeamConfig team = four_robot_team();
  TeamCapabilities caps = capabilities_from(team);
  PlannerOptions options;
  highlevel::HighLevelMap map{highlevel::species_levels(team)};
  PlannerFixture() {
    options = PlannerOptions::from(team.params);
    options.ga_time_budget_s = 0.0;  // generation budget only: deterministic
    options.ga_max_generations = 150;
    map.apply(synthetic_scene(rubble_band_scene()));
  }
  PlanRequest request(int self, const highlevel::HighLevelMap* on = nullptr) const {
    PlanRequest r;
    r.map = on ? on : &map;
    for (const auto& rc : team.robots) r.robots.push_back({rc.id, *team.species_index(rc.species), rc.start_position_m});
    r.self = self;
    return r;
  }
  std::unique_ptr<Planner> planner(const std::string& name) const {
    auto p = PlannerRegistry::builtin().create(name);
    p->configure({caps, options});
    p->activate();
    return p;
  }
  // The same map fed in reverse order (another robot's fusion history).
  std::unique_ptr<highlevel::HighLevelMap> reversed_map() const {
    auto other = std::make_unique<highlevel::HighLevelMap>(highlevel::species_levels(team));
    auto up = synthetic_scene(rubble_band_scene());
    std::reverse(up.upserts.begin(), up.upserts.end());
    std::reverse(up.edge_upserts.begin(), up.edge_upserts.end());
    other->apply(up);
    return other;
  }
};

}  // namespace hexplore::planning::testing
