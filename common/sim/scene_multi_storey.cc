// multi-storey: an open-sided, parking-garage-like building of 32 m x 22 m (x in [0, 32],
// y in [0, 22]) with three levels at z = 0, 3 and 6 (the top one a roof deck under the open
// sky). The upper levels are reached only by climbs the wheeled MR1000 cannot take (slope
// limit 12 deg, step 0.08 m) and the tracked SLUGCAT can (35 deg, 0.25 m):
//   ramp A, 0 -> 1, 16 deg, in a walled bay along the south wall (rising +x);
//   stairs S1, 0 -> 1, 17 risers of 0.176 m on 0.30 m treads, along the east wall (+y);
//   ramp B, 1 -> 2, 18 deg, along the north wall of level 1 (rising -x);
//   stairs S2, 1 -> 2, same flight, along the west wall of level 1 (+y).
// The ground floor has wide entries on every side, level 1 has window bands between piers,
// and an 8 m x 6 m atrium runs through both slabs, so the wheeled robot's gimbal LiDAR sees
// facades, the undersides of the slabs and part of the upper levels from the ground. Every
// hole (ramps, stairs, atrium) has a 1 m parapet on the upper floor except where a climb
// arrives. Robots start south of the building on flat ground.
#include "common/sim/scene_parts.h"

#include <cmath>

namespace hexplore::sim::detail {
namespace {

constexpr double kFloor = 3.0;   // storey height; walking surfaces at 0, 3, 6
constexpr double kSlab = 0.2;
constexpr double kWall = 0.25;
constexpr double kParapet = 1.0;
constexpr double kRail = 0.2;     // parapet and bay-wall thickness
constexpr int kRisers = 17;
constexpr double kRise = kFloor / kRisers;  // 0.176 m: above MR1000's step, within SLUGCAT's
constexpr double kTread = 0.30;             // mean slope 30.5 deg
constexpr double kStairWidth = 1.6;
constexpr double kRampWidth = 2.5;
constexpr double kHeadroom = 2.0;  // slabs are cut open above a climb where it would be lower

double deg(double d) { return d * M_PI / 180.0; }

// Where a climb's slab hole starts: the distance along it at which the climbing surface is
// kHeadroom below the slab's underside.
double hole_start(double slope_tan) { return (kFloor - kSlab - kHeadroom) / slope_tan; }

// A wall along x (y fixed) or y (x fixed) between absolute coordinates, openings given in
// absolute coordinates along it, [bottom, top] above its base.
void wall_x(MeshBuilder& b, double y, double x0, double x1, double z, double h, std::vector<Opening> open) {
  for (auto& o : open) o.from -= x0, o.to -= x0;
  add_wall(b, {x0, y}, {x1, y}, kWall, z, h, std::move(open));
}
void wall_y(MeshBuilder& b, double x, double y0, double y1, double z, double h, std::vector<Opening> open) {
  for (auto& o : open) o.from -= y0, o.to -= y0;
  add_wall(b, {x, y0}, {x, y1}, kWall, z, h, std::move(open));
}

// Window bands of level 1: openings from 1 m above the floor to the slab above, between 1 m
// piers, over [from, to] minus the spans in `solid` (where a climb runs along the wall).
std::vector<Opening> bands(double from, double to, const std::vector<std::pair<double, double>>& solid) {
  std::vector<Opening> out;
  for (double s = from + 1.0; s + 3.0 <= to - 1.0 + 1e-9; s += 4.0) {
    bool clash = false;
    for (const auto& [a, e] : solid) clash = clash || (s < e && s + 3.0 > a);
    if (!clash) out.push_back({s, s + 3.0, 1.0, kFloor});
  }
  return out;
}

}  // namespace

std::vector<Climb> multi_storey_climbs() {
  const double run_a = kFloor / std::tan(deg(16.0)), run_b = kFloor / std::tan(deg(18.0));
  const double stairs = kRisers * kTread;
  return {
      // Ramp A: foot at x = 3.5, top at 3.5 + run_a, in the bay y in [0.25, 2.75].
      {"ramp A (16 deg)", {{1.75, 5.0, 0}, {1.75, 1.5, 0}, {3.5 + run_a + 2.0, 1.5, 0}}, kFloor},
      // Stairs S1: first riser at y = 8, x centre 30.95.
      {"stairs S1", {{30.95, 5.0, 0}, {30.95, 8.0 + stairs + 2.0, 0}}, kFloor},
      // Ramp B: foot at x = 27 on level 1, top at 27 - run_b, bay y in [19.25, 21.75].
      {"ramp B (18 deg)", {{29.5, 17.0, kFloor}, {29.5, 20.5, kFloor}, {27.0 - run_b - 2.0, 20.5, kFloor}}, 2 * kFloor},
      // Stairs S2: first riser at y = 12 on level 1, x centre 1.05.
      {"stairs S2", {{1.05, 9.0, kFloor}, {1.05, 12.0 + stairs + 2.0, kFloor}}, 2 * kFloor},
  };
}

SceneInfo make_multi_storey(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 5));
  MeshBuilder b;
  b.plane(-8, -8, 40, 30, 0.0);
  const Rect inner{kWall, kWall, 32.0 - kWall, 22.0 - kWall};

  // Climbs. Each slab hole starts where the climb has kHeadroom below the slab and ends at
  // the climb's top edge, which is flush with the slab's top.
  const double run_a = kFloor / std::tan(deg(16.0)), run_b = kFloor / std::tan(deg(18.0));
  const double stairs_len = kRisers * kTread;
  const double stairs_hole = std::ceil((kFloor - kSlab - kHeadroom) / kRise - 1.0) * kTread;
  // Ramp A (0 -> 1): bay along the south wall, walled on its north side on the ground floor.
  const double a0 = 3.5, a1 = a0 + run_a;
  b.wedge({a0, kWall, 0.0}, {a1, kWall + kRampWidth, kFloor}, Heading::kPlusX);
  b.box({a0, kWall + kRampWidth, 0.0}, {a1, kWall + kRampWidth + kRail, kFloor - kSlab});
  const Rect hole_a{a0 + hole_start(std::tan(deg(16.0))), kWall, a1, kWall + kRampWidth};
  // Stairs S1 (0 -> 1): along the east wall, walled on its west side on the ground floor.
  const double s1x = inner.x1 - kStairWidth / 2, s1y = 8.0;
  b.stairs({s1x, s1y, 0.0}, Heading::kPlusY, kStairWidth, kRisers, kRise, kTread);
  b.box({inner.x1 - kStairWidth - kRail, s1y, 0.0}, {inner.x1 - kStairWidth, s1y + stairs_len, kFloor - kSlab});
  const Rect hole_s1{inner.x1 - kStairWidth, s1y + stairs_hole, inner.x1, s1y + stairs_len};
  // Ramp B (1 -> 2): along the north wall of level 1, rising towards -x.
  const double b1 = 27.0, b0 = b1 - run_b;
  b.wedge({b0, inner.y1 - kRampWidth, kFloor}, {b1, inner.y1, 2 * kFloor}, Heading::kMinusX);
  b.box({b0, inner.y1 - kRampWidth - kRail, kFloor}, {b1, inner.y1 - kRampWidth, 2 * kFloor - kSlab});
  const Rect hole_b{b0, inner.y1 - kRampWidth, b1 - hole_start(std::tan(deg(18.0))), inner.y1};
  // Stairs S2 (1 -> 2): along the west wall of level 1.
  const double s2x = inner.x0 + kStairWidth / 2, s2y = 12.0;
  b.stairs({s2x, s2y, kFloor}, Heading::kPlusY, kStairWidth, kRisers, kRise, kTread);
  b.box({inner.x0 + kStairWidth, s2y, kFloor}, {inner.x0 + kStairWidth + kRail, s2y + stairs_len, 2 * kFloor - kSlab});
  const Rect hole_s2{inner.x0, s2y + stairs_hole, inner.x0 + kStairWidth, s2y + stairs_len};
  const Rect atrium{12.0, 8.0, 20.0, 14.0};

  // Slabs with their holes, and parapets on them except where a climb arrives (or an
  // exterior wall already stands).
  add_slab(b, inner, kFloor - kSlab, kFloor, {hole_a, hole_s1, atrium});
  add_slab(b, inner, 2 * kFloor - kSlab, 2 * kFloor, {hole_b, hole_s2, atrium});
  add_parapet(b, hole_a, kFloor, kParapet, kRail, {Side::kSouth, Side::kEast});
  add_parapet(b, hole_s1, kFloor, kParapet, kRail, {Side::kEast, Side::kNorth});
  add_parapet(b, hole_b, 2 * kFloor, kParapet, kRail, {Side::kNorth, Side::kWest});
  add_parapet(b, hole_s2, 2 * kFloor, kParapet, kRail, {Side::kWest, Side::kNorth});
  for (int level = 1; level <= 2; ++level) add_parapet(b, atrium, level * kFloor, kParapet, kRail);

  // Exterior walls. Ground floor: wide entries (2.5 m high) and windows, solid where ramp A
  // and stairs S1 run along them. Level 1: window bands, solid along ramp B and stairs S2.
  // Roof deck: a parapet.
  const double y_s = kWall / 2, y_n = 22.0 - kWall / 2, x_w = kWall / 2, x_e = 32.0 - kWall / 2;
  wall_x(b, y_s, 0, 32, 0, kFloor, {{17.0, 23.0, 0, 2.5}, {26.0, 29.0, 0, 2.2}});
  wall_x(b, y_n, 0, 32, 0, kFloor, {{4.0, 9.0, 0, 2.5}, {13.0, 16.0, 1.0, 2.2}, {21.0, 24.0, 1.0, 2.2}, {27.0, 30.0, 0, 2.5}});
  wall_y(b, x_w, kWall, 22 - kWall, 0, kFloor, {{5.0, 9.0, 0, 2.5}, {12.0, 15.0, 1.0, 2.2}, {17.0, 20.0, 1.0, 2.2}});
  wall_y(b, x_e, kWall, 22 - kWall, 0, kFloor, {{2.0, 6.0, 0, 2.5}, {15.0, 19.0, 0, 2.5}});
  wall_x(b, y_s, 0, 32, kFloor, kFloor, bands(0, 32, {}));
  wall_x(b, y_n, 0, 32, kFloor, kFloor, bands(0, 32, {{b0 - 0.5, b1 + 0.5}}));
  wall_y(b, x_w, kWall, 22 - kWall, kFloor, kFloor, bands(kWall, 22 - kWall, {{s2y - 0.5, s2y + stairs_len + 0.5}}));
  wall_y(b, x_e, kWall, 22 - kWall, kFloor, kFloor, bands(kWall, 22 - kWall, {}));
  wall_x(b, y_s, 0, 32, 2 * kFloor, kParapet, {});
  wall_x(b, y_n, 0, 32, 2 * kFloor, kParapet, {});
  wall_y(b, x_w, kWall, 22 - kWall, 2 * kFloor, kParapet, {});
  wall_y(b, x_e, kWall, 22 - kWall, 2 * kFloor, kParapet, {});

  // Columns carrying the slabs, clear of the climbs, the atrium and the parking bays.
  for (const auto& c : {Eigen::Vector2d(8, 6.5), Eigen::Vector2d(8, 15.5), Eigen::Vector2d(24, 6.5),
                                  Eigen::Vector2d(24, 15.5)})
    for (int level = 0; level < 2; ++level)
      b.box({c.x() - 0.2, c.y() - 0.2, level * kFloor}, {c.x() + 0.2, c.y() + 0.2, (level + 1) * kFloor - kSlab});

  // Clutter: cars parked on the ground floor and on level 1, crates on level 1 and the roof
  // deck, a plant box on the deck; stones outside. All clear of the climbs' approaches.
  vehicle(b, {6.5 + rng.uniform(-0.5, 0.5), 11.0 + rng.uniform(-0.3, 0.3)}, rng.uniform(-0.1, 0.1));
  vehicle(b, {24.5 + rng.uniform(-0.5, 0.5), 11.0 + rng.uniform(-0.3, 0.3)}, rng.uniform(-0.1, 0.1));
  vehicle(b, {24.5 + rng.uniform(-0.5, 0.5), 4.0 + rng.uniform(-0.2, 0.2)}, rng.uniform(-0.1, 0.1), kFloor);
  floor_debris(b, rng, Rect{3.0, 4.0, 7.4, 7.5}, 4, 0.6, kFloor);
  floor_debris(b, rng, Rect{21.0, 4.0, 29.0, 12.0}, 5, 0.6, 2 * kFloor);
  b.box({25.0, 15.5, 2 * kFloor}, {27.5 + rng.uniform(0, 0.5), 17.0, 2 * kFloor + 1.2});
  for (int i = 0; i < 6; ++i) stone(b, rng, {rng.uniform(0.0, 32.0), rng.uniform(23.5, 26.0)}, rng.uniform(0.4, 0.8));

  SceneInfo info;
  info.name = "multi-storey";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -5, -0.5), Eigen::Vector3d(34, 27, 7.5));
  info.suggested_starts = {{16, -3, 0}, {18, -3, 0}, {20, -3, 0}, {22, -3, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
