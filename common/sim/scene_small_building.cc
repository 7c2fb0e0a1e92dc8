// small-building: the single-building scene's character on a quarter of its area, with room to
// stand back. A 7 m two-storey building, a one-storey annex whose only door opens onto a walled
// debris yard (steps the wheeled MR1000 cannot take, the tracked SLUGCAT can), rubble against a
// facade, a vehicle and stones, on a ~20 m x 20 m site (x, y in [0, 20]). The ground runs 10 m
// beyond the site on every side, so every facade can be seen within the paper's angle limits
// (45 deg) from somewhere a robot can stand; single-building's 14 m facades can be seen so only
// from the edge of its ground. Small enough for a two-robot team to run out of task views in
// minutes: the scene of the e2e check that a mission ends on "no task views remain".
#include "common/sim/scene_parts.h"

namespace hexplore::sim::detail {

SceneInfo make_small_building(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 6));
  MeshBuilder b;
  b.plane(-10, -10, 40, 40, 0.0);

  BuildingSpec main;
  main.footprint = {3, 3, 11, 11};
  main.floors = 2;
  main.floor_height_m = 3.5;
  main.doors = {{Side::kSouth, 2.0}, {Side::kNorth, 5.0}};
  add_building(b, main);
  add_wall(b, {3.25, 7.0}, {10.75, 7.0}, 0.2, 0.0, 3.3, {{3.0, 4.4, 0, 2.2}});
  floor_debris(b, rng, Rect{4.0, 4.0, 10.0, 6.5}, 4, 0.6, 0.0);

  BuildingSpec annex;
  annex.footprint = {13.5, 3, 18.5, 9};
  annex.floors = 1;
  annex.floor_height_m = 4.0;
  annex.doors = {{Side::kNorth, 1.8}};
  add_building(b, annex);
  floor_debris(b, rng, Rect{14.3, 3.8, 17.7, 6.5}, 3, 0.5, 0.0);

  // Debris yard in front of the annex door, entered through a gap in its north fence.
  add_wall(b, {13.375, 9.0}, {13.375, 13.0}, 0.25, 0.0, 2.0, {});
  add_wall(b, {18.625, 9.0}, {18.625, 13.0}, 0.25, 0.0, 2.0, {});
  add_wall(b, {13.25, 13.125}, {18.75, 13.125}, 0.25, 0.0, 2.0, {{2.0, 4.0, 0, 2.0}});
  debris_field(b, rng, Rect{13.5, 9.0, 18.5, 13.5}, 0.5, 0.10, 0.20);

  rubble_pile(b, rng, {1.8, 8.5}, 1.0, 8, 0.8);
  vehicle(b, {16.0, -2.5}, 0.1);
  rubble_pile(b, rng, {7.0 + rng.uniform(-0.5, 0.5), 16.5}, 1.4, 10, 0.9);
  for (int i = 0; i < 5; ++i) {
    const double x = rng.uniform(1.0, 19.0), y = rng.uniform(14.5, 19.0);
    if (std::abs(x - 8.7) < 2.0 && y < 15.5) continue;  // keep the north door approach free
    stone(b, rng, {x, y}, rng.uniform(0.4, 0.8));
  }

  SceneInfo info;
  info.name = "small-building";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -4, -0.5), Eigen::Vector3d(20, 20, 8));
  info.suggested_starts = {{2, -3, 0}, {4, -3, 0}, {6, -3, 0}, {8, -3, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
