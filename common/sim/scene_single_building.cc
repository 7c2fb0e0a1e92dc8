// single-building: a ~33 m x 33 m site (x, y in [0, 33]) with a tall main building and a
// short annex whose only door opens onto a walled debris yard. The debris steps (0.10-0.20 m)
// exceed the wheeled MR1000's step limit (0.08 m) but not the tracked SLUGCAT's (0.25 m), so
// the annex's indoor space needs the tracked robot. Robots start south of the site
// (default team: (2, -3) and (4, -3)) on flat ground.
#include "common/sim/scene_parts.h"

namespace hexplore::sim::detail {

SceneInfo make_single_building(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 1));
  MeshBuilder b;
  b.plane(-8, -10, 41, 41, 0.0);

  // Main building: 17 m x 17 m, four floors of 3.5 m (14 m tall). Stairs from the ground
  // floor to the first floor run along the east wall.
  BuildingSpec main;
  main.footprint = {3, 2, 20, 19};
  main.floors = 4;
  main.floor_height_m = 3.5;
  main.doors = {{Side::kSouth, 3.0}, {Side::kSouth, 12.0}, {Side::kNorth, 8.0}, {Side::kWest, 9.0}};
  main.slab_holes = {{Rect{18.15, 4.3, 19.75, 10.1}}};
  add_building(b, main);
  b.stairs({18.95, 4.5, 0.0}, Heading::kPlusY, 1.4, 20, 0.175, 0.28);
  // Ground-floor rooms: a wall along y = 10.5 and one along x = 11.5, each with doors.
  add_wall(b, {3.25, 10.5}, {16.5, 10.5}, 0.2, 0.0, 3.3, {{3.0, 4.4, 0, 2.2}, {8.5, 9.9, 0, 2.2}});
  add_wall(b, {11.5, 2.25}, {11.5, 10.4}, 0.2, 0.0, 3.3, {{3.0, 4.4, 0, 2.2}});
  // First floor: one wall splitting it east-west, with two doors.
  add_wall(b, {11.5, 2.25}, {11.5, 18.75}, 0.2, 3.5, 3.3, {{4.0, 5.4, 0, 2.2}, {12.0, 13.4, 0, 2.2}});
  floor_debris(b, rng, Rect{4.0, 3.0, 10.5, 9.5}, 6, 0.7, 0.0);
  floor_debris(b, rng, Rect{4.0, 12.0, 10.5, 18.0}, 5, 0.7, 3.5);

  // Annex: 8 m x 12 m, one 5 m storey; its only door faces the debris yard to the north.
  BuildingSpec annex;
  annex.footprint = {23.5, 2, 31.5, 14};
  annex.floors = 1;
  annex.floor_height_m = 5.0;
  annex.doors = {{Side::kNorth, 3.0}};
  add_building(b, annex);
  floor_debris(b, rng, Rect{24.5, 3.0, 30.5, 9.0}, 5, 0.6, 0.0);

  // Debris yard: fenced on three sides, entered through a gap in the north fence; debris
  // covers all of it, from the gap to the annex door.
  add_wall(b, {23.125, 14.0}, {23.125, 21.0}, 0.25, 0.0, 2.5, {});
  add_wall(b, {31.875, 14.0}, {31.875, 21.0}, 0.25, 0.0, 2.5, {});
  add_wall(b, {23.0, 21.125}, {32.0, 21.125}, 0.25, 0.0, 2.5, {{5.0, 7.5, 0, 2.5}});
  debris_field(b, rng, Rect{23.25, 14.0, 31.75, 21.5}, 0.5, 0.10, 0.20);

  // Damage: a floor slab fallen against the north facade (an overhang to drive under or
  // not, by clearance) and wall rubble heaped against the west facade, clear of the doors.
  b.oriented_box({16.0, 20.4, 1.55}, {2.0, 1.6, 0.12}, 0.0, 0.0, -1.05);
  rubble_pile(b, rng, {2.0, 16.5}, 1.4, 12, 1.1);

  // Outdoors: a vehicle, rubble piles and stones, away from the start area and the doors.
  vehicle(b, {27.0, -3.5}, 0.1);
  rubble_pile(b, rng, {22.0 + rng.uniform(-0.5, 0.5), 26.0}, 2.0, 14, 1.2);
  rubble_pile(b, rng, {7.0, 26.0 + rng.uniform(-0.5, 0.5)}, 1.8, 12, 1.0);
  rubble_pile(b, rng, {-1.0, 12.0}, 1.2, 8, 0.8);
  for (int i = 0; i < 8; ++i) {
    const double x = rng.uniform(1.0, 32.0), y = rng.uniform(23.0, 32.0);
    if (std::abs(x - 11.7) < 2.5 && y < 25.0) continue;  // keep the north door approach free
    stone(b, rng, {x, y}, rng.uniform(0.4, 0.9));
  }

  SceneInfo info;
  info.name = "single-building";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -6, -0.5), Eigen::Vector3d(34, 34, 15));
  info.suggested_starts = {{2, -3, 0}, {4, -3, 0}, {6, -3, 0}, {8, -3, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
