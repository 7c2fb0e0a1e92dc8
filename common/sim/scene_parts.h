#pragma once
// Shared pieces of the procedural scenes (internal to common/sim): clutter generators and
// the per-scene builders that scenes.cc dispatches to.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/sim/building.h"
#include "common/sim/mesh_builder.h"
#include "common/core/rng.h"
#include "common/sim/scenes.h"

namespace hexplore::sim::detail {

// A heap of tumbled blocks around `center` within `radius`, up to `max_height` tall.
void rubble_pile(MeshBuilder& b, core::SimRng& rng, const Eigen::Vector2d& center, double radius, int blocks,
                 double max_height);
// A single stone (tilted block) resting on the ground.
void stone(MeshBuilder& b, core::SimRng& rng, const Eigen::Vector2d& center, double size);
// A car-sized vehicle (body and cabin) parked at `center` with heading `yaw`.
void vehicle(MeshBuilder& b, const Eigen::Vector2d& center, double yaw, double base_z = 0.0);
// A field of square cells of random height in [min_h, max_h] covering `area` (debris that
// only a robot with a large enough step limit crosses).
void debris_field(MeshBuilder& b, core::SimRng& rng, const Rect& area, double cell, double min_h, double max_h,
                  double base_z = 0.0);
// Loose debris blocks on a floor inside `area`.
void floor_debris(MeshBuilder& b, core::SimRng& rng, const Rect& area, int blocks, double max_size, double floor_z);

// A climb between two floors of a generated scene, as a path a robot follows from the lower
// floor (path.front(), facing the second point) up to the upper floor at height top_z. Tests
// drive robots along it; the scene and the tests share it so they cannot drift apart.
struct Climb {
  std::string name;
  std::vector<Eigen::Vector3d> path;
  double top_z = 0.0;
};
// The ramps and stairs of the multi-storey scene (the same for every seed).
std::vector<Climb> multi_storey_climbs();

// The office scene's floor plan (what the generator builds walls from; tests check doors and
// rooms against it).
struct OfficeRoom {
  Rect interior;                 // floor inside the room's walls
  Rect door;                     // the gap through the corridor wall (its full thickness)
  double door_width_m = 0.0;
  bool door_faces_north = false;  // the door wall is the room's north wall (else its south one)
};
struct OfficeLayout {
  Rect footprint;
  std::vector<Rect> corridors;  // clear floor of the long and cross corridors
  std::vector<OfficeRoom> rooms;
};
OfficeLayout office_layout(uint64_t seed);

// The campus scene's buildings (the same for every seed; rooms, room doors and clutter
// follow it) and its climbs: every flight between storeys, the parking deck's ramp and the
// lab's plinth steps (tests check levels and who climbs what against them).
struct CampusBuilding {
  std::string name;
  Rect footprint;
  double base_z = 0.0;    // ground-floor level (the lab stands on a plinth)
  int floors = 1;         // walkable levels inside (the parking deck: ground and roof deck)
  double storey_m = 0.0;  // floor k at base_z + k * storey_m
};
std::vector<CampusBuilding> campus_buildings();
std::vector<Climb> campus_climbs();

SceneInfo make_single_building(uint64_t seed);
SceneInfo make_small_building(uint64_t seed);
SceneInfo make_multi_building(uint64_t seed);
SceneInfo make_corridor_stairs(uint64_t seed);
SceneInfo make_office(uint64_t seed);
SceneInfo make_multi_storey(uint64_t seed);
SceneInfo make_campus(uint64_t seed);

}  // namespace hexplore::sim::detail
