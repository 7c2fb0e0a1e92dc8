#pragma once
// Shared pieces of the procedural scenes (internal to common/sim): clutter generators and
// the per-scene builders that scenes.cc dispatches to.

#include <cstdint>

#include <Eigen/Core>

#include "common/sim/building.h"
#include "common/sim/mesh_builder.h"
#include "common/sim/rng.h"
#include "common/sim/scenes.h"

namespace hexplore::sim::detail {

// A heap of tumbled blocks around `center` within `radius`, up to `max_height` tall.
void rubble_pile(MeshBuilder& b, Rng& rng, const Eigen::Vector2d& center, double radius, int blocks,
                 double max_height);
// A single stone (tilted block) resting on the ground.
void stone(MeshBuilder& b, Rng& rng, const Eigen::Vector2d& center, double size);
// A car-sized vehicle (body and cabin) parked at `center` with heading `yaw`.
void vehicle(MeshBuilder& b, const Eigen::Vector2d& center, double yaw, double base_z = 0.0);
// A field of square cells of random height in [min_h, max_h] covering `area` (debris that
// only a robot with a large enough step limit crosses).
void debris_field(MeshBuilder& b, Rng& rng, const Rect& area, double cell, double min_h, double max_h,
                  double base_z = 0.0);
// Loose debris blocks on a floor inside `area`.
void floor_debris(MeshBuilder& b, Rng& rng, const Rect& area, int blocks, double max_size, double floor_z);

SceneInfo make_single_building(uint64_t seed);
SceneInfo make_multi_building(uint64_t seed);
SceneInfo make_corridor_stairs(uint64_t seed);

}  // namespace hexplore::sim::detail
