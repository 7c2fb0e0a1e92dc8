// corridor-stairs: like the paper's field experiment, a 36 m x 10 m building with three
// floors of 3.2 m: a 3 m corridor along x (y in [7.5, 10.5]) with rooms on both sides, a
// stair hall at each end (x < 8, x > 28), and two entrances from the outdoor platform on its
// south side (y < 4). Stairs 0->1 run along the north wall of both halls, stairs 1->2 along
// the south wall of the east hall.
#include "common/sim/scene_parts.h"

namespace hexplore::sim::detail {

SceneInfo make_corridor_stairs(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 3));
  MeshBuilder b;
  b.plane(-6, -10, 42, 20, 0.0);

  constexpr double kFloor = 3.2;
  constexpr int kSteps = 18;
  BuildingSpec s;
  s.footprint = {0, 4, 36, 14};
  s.floors = 3;
  s.floor_height_m = kFloor;
  s.doors = {{Side::kSouth, 2.5}, {Side::kSouth, 32.0}};
  s.slab_holes = {{Rect{1.6, 12.0, 6.64, 13.75}, Rect{29.36, 12.0, 34.4, 13.75}}, {Rect{29.36, 4.25, 34.4, 6.0}}};
  add_building(b, s);
  // Each flight starts 1.35 m from the end wall (room to line up) and ends on a landing.
  b.stairs({1.6, 12.9, 0.0}, Heading::kPlusX, 1.4, kSteps, kFloor / kSteps, 0.28);
  b.stairs({34.4, 12.9, 0.0}, Heading::kMinusX, 1.4, kSteps, kFloor / kSteps, 0.28);
  b.stairs({34.4, 5.1, kFloor}, Heading::kMinusX, 1.4, kSteps, kFloor / kSteps, 0.28);

  // Rooms between the halls (x in [8, 28]), four per side, on every floor.
  for (int floor = 0; floor < s.floors; ++floor) {
    const double z = floor * kFloor, h = kFloor - 0.2;
    std::vector<Opening> doors;
    for (int r = 0; r < 4; ++r) doors.push_back({1.8 + 5.0 * r, 3.2 + 5.0 * r, 0, 2.2});
    add_wall(b, {8.0, 7.5}, {28.0, 7.5}, 0.2, z, h, doors);
    add_wall(b, {8.0, 10.5}, {28.0, 10.5}, 0.2, z, h, doors);
    for (double x : {8.0, 13.0, 18.0, 23.0, 28.0}) {
      add_wall(b, {x, 4.25}, {x, 7.4}, 0.2, z, h, {});
      add_wall(b, {x, 10.6}, {x, 13.75}, 0.2, z, h, {});
    }
    for (int r = 0; r < 4; ++r) {
      floor_debris(b, rng, Rect{8.5 + 5.0 * r, 4.5, 12.5 + 5.0 * r, 6.3}, 2, 0.6, z);
      floor_debris(b, rng, Rect{8.5 + 5.0 * r, 11.7, 12.5 + 5.0 * r, 13.5}, 2, 0.6, z);
    }
  }
  // Platform clutter: crates and barriers south of the building.
  for (int i = 0; i < 5; ++i)
    b.oriented_box({rng.uniform(8.0, 28.0), rng.uniform(-6.0, 0.0), 0.4}, {0.5, 0.4, 0.4}, rng.uniform(0, M_PI));
  vehicle(b, {38.5, -3.0}, M_PI / 2);

  SceneInfo info;
  info.name = "corridor-stairs";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -8, -0.5), Eigen::Vector3d(39, 16, 10));
  info.suggested_starts = {{2, -3, 0}, {4, -3, 0}, {32, -3, 0}, {34, -3, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
