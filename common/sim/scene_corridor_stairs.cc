// corridor-stairs: like the paper's field experiment, a 36 m x 10 m building with three
// floors of 3.2 m: a 3 m corridor along x with rooms on both sides, a stair hall at each
// end, and two entrances from the outdoor platform on its south side (y < 4). Stairs 0->1
// run along the north wall of both halls, stairs 1->2 along the south wall of the east hall.
#include "common/sim/scene_parts.h"

namespace hexplore::sim::detail {

SceneInfo make_corridor_stairs(uint64_t seed) {
  Rng rng(mix_seed(seed, 3));
  MeshBuilder b;
  b.plane(-6, -10, 42, 20, 0.0);

  constexpr double kFloor = 3.2;
  constexpr int kSteps = 18;
  BuildingSpec s;
  s.footprint = {0, 4, 36, 14};
  s.floors = 3;
  s.floor_height_m = kFloor;
  s.doors = {{Side::kSouth, 2.5}, {Side::kSouth, 32.0}};
  s.slab_holes = {{Rect{0.25, 12.0, 5.9, 13.75}, Rect{30.1, 12.0, 35.75, 13.75}}, {Rect{30.1, 4.25, 35.75, 6.0}}};
  add_building(b, s);
  b.stairs({0.6, 12.9, 0.0}, Heading::kPlusX, 1.4, kSteps, kFloor / kSteps, 0.28);
  b.stairs({35.4, 12.9, 0.0}, Heading::kMinusX, 1.4, kSteps, kFloor / kSteps, 0.28);
  b.stairs({35.4, 5.1, kFloor}, Heading::kMinusX, 1.4, kSteps, kFloor / kSteps, 0.28);

  // Rooms between the halls (x in [7, 29]), four per side, on every floor.
  for (int floor = 0; floor < s.floors; ++floor) {
    const double z = floor * kFloor, h = kFloor - 0.2;
    std::vector<Opening> doors;
    for (int r = 0; r < 4; ++r) doors.push_back({2.0 + 5.5 * r, 3.4 + 5.5 * r, 0, 2.2});
    add_wall(b, {7.0, 7.5}, {29.0, 7.5}, 0.2, z, h, doors);
    add_wall(b, {7.0, 10.5}, {29.0, 10.5}, 0.2, z, h, doors);
    for (double x : {7.0, 12.5, 18.0, 23.5, 29.0}) {
      add_wall(b, {x, 4.25}, {x, 7.4}, 0.2, z, h, {});
      add_wall(b, {x, 10.6}, {x, 13.75}, 0.2, z, h, {});
    }
    for (int r = 0; r < 4; ++r) {
      floor_debris(b, rng, Rect{7.5 + 5.5 * r, 4.5, 12.0 + 5.5 * r, 6.5}, 2, 0.6, z);
      floor_debris(b, rng, Rect{7.5 + 5.5 * r, 11.5, 12.0 + 5.5 * r, 13.5}, 2, 0.6, z);
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
