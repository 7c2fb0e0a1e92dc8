// multi-building: a ~39.4 m x 39.4 m site (~1,554 m2, x, y in [0, 39.4]) with three
// buildings (~1,014, ~1,365 and ~3,960 m3) that have rooms, interior debris and stairs
// between floors, surrounded by rubble, rough ground, an outdoor terrace reached by steps,
// stones and vehicles. Robots start in the open street around (17-22, 1-4).
#include "common/sim/scene_parts.h"

namespace hexplore::sim::detail {

SceneInfo make_multi_building(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 2));
  MeshBuilder b;
  b.plane(-6, -8, 46, 46, 0.0);

  // B1: 13 x 13 m, two floors of 3 m (~1,014 m3); stairs along the west wall.
  BuildingSpec b1;
  b1.footprint = {2, 2, 15, 15};
  b1.floors = 2;
  b1.floor_height_m = 3.0;
  b1.doors = {{Side::kEast, 5.0}, {Side::kNorth, 4.0}};
  b1.slab_holes = {{Rect{2.25, 4.8, 3.9, 9.76}}};
  add_building(b, b1);
  b.stairs({3.0, 5.0, 0.0}, Heading::kPlusY, 1.4, 17, 3.0 / 17, 0.28);
  add_wall(b, {4.0, 10.5}, {14.75, 10.5}, 0.2, 0.0, 2.8, {{3.0, 4.4, 0, 2.2}});
  add_wall(b, {9.0, 2.25}, {9.0, 10.4}, 0.2, 0.0, 2.8, {{4.0, 5.4, 0, 2.2}});
  floor_debris(b, rng, Rect{4.5, 2.5, 8.5, 9.5}, 5, 0.6, 0.0);
  floor_debris(b, rng, Rect{4.5, 8.0, 14.5, 14.5}, 4, 0.6, 3.0);

  // B2: 13 x 15 m, two floors of 3.5 m (~1,365 m3); stairs along the east wall.
  BuildingSpec b2;
  b2.footprint = {24, 2, 37, 17};
  b2.floors = 2;
  b2.floor_height_m = 3.5;
  b2.doors = {{Side::kWest, 6.0}, {Side::kNorth, 5.0}};
  b2.slab_holes = {{Rect{35.15, 3.8, 36.75, 9.6}}};
  add_building(b, b2);
  b.stairs({35.95, 4.0, 0.0}, Heading::kPlusY, 1.4, 20, 0.175, 0.28);
  add_wall(b, {24.25, 11.0}, {34.8, 11.0}, 0.2, 0.0, 3.3, {{5.0, 6.4, 0, 2.2}});
  add_wall(b, {30.0, 11.1}, {30.0, 16.75}, 0.2, 0.0, 3.3, {{2.0, 3.4, 0, 2.2}});
  floor_debris(b, rng, Rect{25.0, 3.0, 33.0, 10.0}, 6, 0.7, 0.0);
  floor_debris(b, rng, Rect{25.0, 11.0, 36.0, 16.0}, 4, 0.6, 3.5);

  // B3: 20 x 16.5 m, three floors of 4 m (~3,960 m3); stairs 0->1 along the west wall and
  // 1->2 along the east wall.
  BuildingSpec b3;
  b3.footprint = {2, 21, 22, 37.5};
  b3.floors = 3;
  b3.floor_height_m = 4.0;
  b3.doors = {{Side::kSouth, 5.0}, {Side::kSouth, 14.0}, {Side::kEast, 8.0}};
  b3.slab_holes = {{Rect{2.25, 23.8, 3.9, 30.44}}, {Rect{20.1, 23.8, 21.75, 30.44}}};
  add_building(b, b3);
  b.stairs({3.0, 24.0, 0.0}, Heading::kPlusY, 1.4, 23, 4.0 / 23, 0.28);
  b.stairs({21.0, 24.0, 4.0}, Heading::kPlusY, 1.4, 23, 4.0 / 23, 0.28);
  add_wall(b, {4.0, 31.5}, {19.5, 31.5}, 0.2, 0.0, 3.8, {{3.0, 4.4, 0, 2.2}, {10.0, 11.4, 0, 2.2}});
  add_wall(b, {12.0, 21.25}, {12.0, 31.4}, 0.2, 0.0, 3.8, {{4.0, 5.4, 0, 2.2}});
  add_wall(b, {4.0, 31.5}, {19.5, 31.5}, 0.2, 4.0, 3.8, {{6.0, 7.4, 0, 2.2}});
  floor_debris(b, rng, Rect{4.5, 22.0, 11.5, 30.5}, 7, 0.8, 0.0);
  floor_debris(b, rng, Rect{12.5, 32.0, 19.5, 37.0}, 5, 0.7, 0.0);
  floor_debris(b, rng, Rect{5.0, 32.0, 19.0, 37.0}, 5, 0.7, 4.0);

  // Damage: a roof slab of B2 slid down its east facade, another leaning on B3's west wall.
  b.oriented_box({38.0, 12.0, 2.6}, {0.12, 3.0, 2.9}, 0.0, 0.45, 0.0);
  b.oriented_box({1.0, 33.0, 1.8}, {0.12, 2.5, 2.0}, 0.0, -0.4, 0.0);

  // Outdoors: rough ground (low irregular slabs), rubble heaps, a terrace reached by steps,
  // stones and vehicles. The street x in [15, 24], y < 20 stays open for the start area.
  debris_field(b, rng, Rect{24.0, 19.5, 30.0, 24.5}, 1.0, 0.02, 0.07);
  rubble_pile(b, rng, {27.0 + rng.uniform(-0.5, 0.5), 30.0}, 2.2, 16, 1.4);
  rubble_pile(b, rng, {36.0, 21.5}, 1.5, 10, 1.0);
  rubble_pile(b, rng, {8.5, 18.0 + rng.uniform(-0.3, 0.3)}, 1.5, 10, 0.9);
  // Terrace 1.2 m high in the north-east corner; six steps on its west side.
  b.box({32.0, 33.0, 0.0}, {39.0, 39.0, 1.2});
  b.stairs({30.2, 36.0, 0.0}, Heading::kPlusX, 1.6, 6, 0.2, 0.3);
  for (int i = 0; i < 4; ++i) stone(b, rng, {rng.uniform(33.0, 38.0), rng.uniform(33.5, 38.5)}, 0.5);
  vehicle(b, {31.0, -3.0}, 0.2);
  vehicle(b, {9.0, -3.5}, -0.1);
  vehicle(b, {33.0 + rng.uniform(-0.5, 0.5), 26.5}, 1.4);
  for (int i = 0; i < 10; ++i) {
    // Stones in the open ground west of B2 and north of B1, clear of the street's centre.
    const double x = rng.uniform(0.5, 14.0), y = rng.uniform(16.0, 20.0);
    stone(b, rng, {x, y}, rng.uniform(0.4, 1.0));
  }
  for (int i = 0; i < 6; ++i) stone(b, rng, {rng.uniform(23.0, 38.0), rng.uniform(18.0, 19.0)}, rng.uniform(0.4, 0.8));
  SceneInfo info;
  info.name = "multi-building";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, -0.5), Eigen::Vector3d(39.4, 39.4, 13));
  info.suggested_starts = {{17, 2, 0}, {19, 2, 0}, {21, 2, 0}, {17, 4, 0}, {19, 4, 0}, {21, 4, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
