// campus: a 100 m x 100 m site (x, y in [0, 100]) for large heterogeneous teams: five
// buildings of two or three storeys (3.4 m) with rooms, corridors and stairs, an open parking
// deck with a ramp, rubble, vehicles and rough ground, streets between them (an avenue along
// x in [42, 58], a street along y in [44, 56]). The five buildings share one plan: a stair hall at
// each end and rooms either side of a corridor between them; their flights (23 risers of 0.148 m on
// 0.30 m treads, 26 deg) alternate between the halls. Who gets where:
//   hall (B1, 3 storeys), library (B2, 2), dorm (B5, 3): flat entrances, so the wheeled MR1000
//     explores their ground floors (room doors 0.90-1.20 m); upper floors by stairs only;
//   lab (B3, 2 storeys): on a 0.60 m plinth reached by two flights of steps: the quadruped's
//     and the SLUGCAT's; its room doors are 0.80-0.90 m;
//   workshop (B4, 2 storeys): its only door opens onto a fenced yard of fallen masonry slabs
//     0.21-0.23 m high, a step the SLUGCAT (0.25 m) climbs and the quadruped (0.20 m) does
//     not: the tracked robot's alone;
//   parking deck (B6): ground level open between columns; the roof deck by a 16 deg ramp.
// What no climbing robot reaches from close up, the MR1000's long-range LiDAR sees from the
// streets. Robots start along the south edge (y = -3, every 6 m from x = 5 to 95).
#include "common/sim/scene_parts.h"

#include <algorithm>
#include <cmath>

namespace hexplore::sim::detail {
namespace {

constexpr double kStorey = 3.4;
constexpr double kSlab = 0.2;
constexpr double kWall = 0.25;       // exterior walls
constexpr double kPartition = 0.15;  // interior walls
constexpr double kDoorHeight = 2.1;  // room doors
// Flights the quadruped's own map reads as its ground: on 0.175 m risers at 30-32 deg (the
// older scenes' flights) the voxel steps and slopes it maps exceed its 0.20 m and 30 deg, though
// its body climbs them; on these they do not (tests/highlevel/climb_graph_test.cc).
constexpr int kRisers = 23;
constexpr double kRise = kStorey / kRisers;  // 0.148 m
constexpr double kTread = 0.30;              // 26.2 deg
constexpr double kStairWidth = 1.4;
constexpr double kStairFoot = 2.25;  // floor between a hall's south wall and its flight's foot
constexpr double kHall = 4.5;        // stair halls at both ends of a block
constexpr double kCorridor = 2.0;
constexpr double kHeadroom = 2.0;    // slabs are open above a flight where it would be lower
constexpr double kParapet = 1.0;
constexpr double kRail = 0.2;
constexpr double kPlinth = 4 * 0.15;  // the lab's plinth: four risers
constexpr double kRampDeg = 16.0;

// One of the five buildings of one plan: its place, storeys, exterior doors (BuildingSpec's,
// 1.6 m wide) and the width range of its room doors.
struct Block {
  CampusBuilding where;
  std::vector<BuildingSpec::Door> doors;
  double room_door_min_m, room_door_max_m;
};

std::vector<Block> blocks() {
  // Doors into the west hall stay clear of its flight (x0 + 0.25 .. x0 + 1.85, y0 + 2.5 ..
  // y0 + 9.4 on the ground floor).
  const double w = 1.6, h = 2.2;
  return {
      {{"hall", {6, 10, 38, 26}, 0.0, 3, kStorey},
       {{Side::kSouth, 2.4, w, h}, {Side::kSouth, 28.4, w, h}, {Side::kNorth, 28.4, w, h}, {Side::kWest, 11.0, w, h}},
       1.0, 1.2},
      {{"library", {62, 10, 92, 28}, 0.0, 2, kStorey},
       {{Side::kSouth, 2.4, w, h}, {Side::kSouth, 26.4, w, h}, {Side::kEast, 9.0, w, h}}, 0.9, 1.0},
      {{"lab", {8, 64, 34, 80}, kPlinth, 2, kStorey}, {{Side::kSouth, 2.4, w, h}, {Side::kEast, 3.0, w, h}}, 0.8, 0.9},
      {{"workshop", {76, 58, 96, 72}, 0.0, 2, kStorey}, {{Side::kWest, 10.5, w, h}}, 0.9, 1.1},
      {{"dorm", {60, 82, 94, 96}, 0.0, 3, kStorey},
       {{Side::kSouth, 2.4, w, h}, {Side::kSouth, 30.4, w, h}, {Side::kWest, 10.0, w, h}}, 1.0, 1.2},
  };
}

const CampusBuilding kDeck{"parking deck", {6, 30, 32, 42}, 0.0, 2, kStorey};
constexpr double kRampFootX = 10.0;  // the deck's ramp rises +x from here, in a bay along its south side
constexpr double kRampWidth = 2.5;

double ramp_run() { return kStorey / std::tan(kRampDeg * M_PI / 180.0); }

// Flight k (floor k -> k + 1) of a block: along the west wall of the west hall for
// even k, the east wall of the east hall for odd k, climbing +y from kStairFoot off the south wall.
Eigen::Vector3d flight_foot(const CampusBuilding& c, int k) {
  const Rect& f = c.footprint;
  const double x = k % 2 == 0 ? f.x0 + kWall + kStairWidth / 2 : f.x1 - kWall - kStairWidth / 2;
  return {x, f.y0 + kWall + kStairFoot, c.base_z + k * kStorey};
}

// One storey's rooms between the halls: a corridor along x through the middle, a row of rooms
// either side (3.5-5 m wide, the last one or two 2.5-5 m, seeded), each with one door onto the
// corridor; some rooms hold loose debris.
void storey_rooms(MeshBuilder& b, core::SimRng& rng, const Block& t, int floor) {
  const Rect& f = t.where.footprint;
  const double z = t.where.base_z + floor * kStorey, h = kStorey - kSlab;
  const double xa = f.x0 + kHall, xb = f.x1 - kHall, cy = 0.5 * (f.y0 + f.y1);
  struct Row {
    double y0, y1, door_y;
  };
  const Row rows[2] = {{f.y0 + kWall, cy - kCorridor / 2 - kPartition / 2, cy - kCorridor / 2},
                       {cy + kCorridor / 2 + kPartition / 2, f.y1 - kWall, cy + kCorridor / 2}};
  for (const Row& row : rows) {
    std::vector<double> cuts = {xa};
    while (xb - cuts.back() > 8.5) cuts.push_back(cuts.back() + rng.uniform(3.5, 5.0));
    if (xb - cuts.back() > 5.0) cuts.push_back(0.5 * (cuts.back() + xb));
    cuts.push_back(xb);
    std::vector<Opening> doors;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double x0 = cuts[i] + kPartition / 2, x1 = cuts[i + 1] - kPartition / 2;
      const double w = rng.uniform(t.room_door_min_m, t.room_door_max_m), margin = 0.3 + w / 2;
      const double centre = rng.uniform(x0 + margin, x1 - margin);
      doors.push_back({centre - w / 2 - xa, centre + w / 2 - xa, 0.0, kDoorHeight});
      if (i > 0) add_wall(b, {cuts[i], row.y0}, {cuts[i], row.y1}, kPartition, z, h, {});
      if (rng.chance(0.3)) floor_debris(b, rng, Rect{x0 + 0.3, row.y0 + 0.3, x1 - 0.3, row.y1 - 0.3}, 3, 0.6, z);
    }
    add_wall(b, {xa, row.door_y}, {xb, row.door_y}, kPartition, z, h, doors);
    for (double x : {xa, xb}) add_wall(b, {x, row.y0}, {x, row.y1}, kPartition, z, h, {});
  }
}

// A block: shell (add_building), flights with their slab holes, a wall beside each
// flight on the floor below and a parapet round its hole on the floor above (open where the
// flight arrives and along the exterior wall), and every storey's rooms.
void block(MeshBuilder& b, core::SimRng& rng, const Block& t) {
  const CampusBuilding& c = t.where;
  const double run = kRisers * kTread;
  const double hole_from = std::ceil((kStorey - kSlab - kHeadroom) / kRise - 1.0) * kTread;
  BuildingSpec shell;
  shell.footprint = c.footprint;
  shell.base_z_m = c.base_z;
  shell.floors = c.floors;
  shell.floor_height_m = kStorey;
  shell.wall_m = kWall;
  shell.slab_m = kSlab;
  shell.doors = t.doors;
  shell.window_spacing_m = 4.0;
  std::vector<Rect> holes;
  for (int k = 0; k + 1 < c.floors; ++k) {
    const Eigen::Vector3d foot = flight_foot(c, k);
    holes.push_back({foot.x() - kStairWidth / 2, foot.y() + hole_from, foot.x() + kStairWidth / 2, foot.y() + run});
    shell.slab_holes.push_back({holes.back()});
  }
  add_building(b, shell);
  for (int k = 0; k + 1 < c.floors; ++k) {
    const Eigen::Vector3d foot = flight_foot(c, k);
    const bool west = k % 2 == 0;
    b.stairs(foot, Heading::kPlusY, kStairWidth, kRisers, kRise, kTread);
    const double inner = west ? foot.x() + kStairWidth / 2 : foot.x() - kStairWidth / 2 - kRail;
    b.box({inner, foot.y(), foot.z()}, {inner + kRail, foot.y() + run, foot.z() + kStorey - kSlab});
    const Side wall_side = west ? Side::kWest : Side::kEast;
    add_parapet(b, holes[size_t(k)], foot.z() + kStorey, kParapet, kRail, {wall_side, Side::kNorth});
  }
  for (int floor = 0; floor < c.floors; ++floor) storey_rooms(b, rng, t, floor);
}

// The parking deck: columns carry a roof deck over an open ground level; the ramp runs in a
// walled bay along the south side; a parapet runs round the deck's edge and the ramp's hole
// (open where the ramp arrives). Cars on both levels, clear of the ramp and the lane north of it.
void parking_deck(MeshBuilder& b, core::SimRng& rng) {
  const Rect& f = kDeck.footprint;
  const double a0 = kRampFootX, a1 = a0 + ramp_run(), y0 = f.y0 + kRail, y1 = y0 + kRampWidth;
  b.wedge({a0, y0, 0.0}, {a1, y1, kStorey}, Heading::kPlusX);
  b.box({a0, f.y0, 0.0}, {a1, y0, kStorey - kSlab});
  b.box({a0, y1, 0.0}, {a1, y1 + kRail, kStorey - kSlab});
  const Rect hole{a0 + (kStorey - kSlab - kHeadroom) / std::tan(kRampDeg * M_PI / 180.0), y0, a1, y1};
  add_slab(b, f, kStorey - kSlab, kStorey, {hole});
  add_parapet(b, hole, kStorey, kParapet, kRail, {Side::kEast, Side::kSouth});
  const double top = kStorey + kParapet;
  b.box({f.x0, f.y0, kStorey}, {f.x1, f.y0 + kRail, top});
  b.box({f.x0, f.y1 - kRail, kStorey}, {f.x1, f.y1, top});
  b.box({f.x0, f.y0 + kRail, kStorey}, {f.x0 + kRail, f.y1 - kRail, top});
  b.box({f.x1 - kRail, f.y0 + kRail, kStorey}, {f.x1, f.y1 - kRail, top});
  for (double x : {f.x0 + 0.2, 14.0, 22.0, f.x1 - 0.2})
    for (double y : {35.0, f.y1 - 0.2}) b.box({x - 0.2, y - 0.2, 0.0}, {x + 0.2, y + 0.2, kStorey - kSlab});
  for (double x : {9.5, 18.0, 26.5})
    if (rng.chance(0.8)) vehicle(b, {x + rng.uniform(-0.3, 0.3), 38.5}, M_PI / 2 + rng.uniform(-0.05, 0.05));
  vehicle(b, {12.0 + rng.uniform(-0.5, 0.5), 38.5}, M_PI / 2, kStorey);
  vehicle(b, {27.0 + rng.uniform(-0.5, 0.5), 37.0}, rng.uniform(-0.2, 0.2), kStorey);
}

// The lab's plinth with its two flights of steps (to the south door and the east door), each
// between cheek walls. Their 0.35 m treads are deeper than the flights' indoors: on four steps
// of 0.30 m the quadruped's map read a step above its 0.20 m somewhere on the flight.
void plinth(MeshBuilder& b) {
  b.box({5, 60, 0}, {37, 83, kPlinth});
  b.stairs({11.2, 58.6, 0}, Heading::kPlusY, 2.0, 4, kPlinth / 4, 0.35);
  for (double x : {10.0, 12.2}) b.box({x, 58.6, 0}, {x + kRail, 60, kPlinth + kParapet});
  b.stairs({38.4, 67.8, 0}, Heading::kMinusX, 2.0, 4, kPlinth / 4, 0.35);
  for (double y : {66.6, 68.8}) b.box({37, y, 0}, {38.4, y + kRail, kPlinth + kParapet});
}

// The workshop's yard (x in [64, 76], y in [58, 72]): fenced on the south, west and north,
// entered through a gap in the west fence, and paved wall to wall with fallen slabs.
void masonry_yard(MeshBuilder& b, core::SimRng& rng) {
  add_wall(b, {64, 57.875}, {76, 57.875}, 0.25, 0.0, 2.5, {});
  add_wall(b, {64, 72.125}, {76, 72.125}, 0.25, 0.0, 2.5, {});
  add_wall(b, {63.875, 57.75}, {63.875, 72.25}, 0.25, 0.0, 2.5, {{5.25, 8.25, 0.0, 2.5}});
  debris_field(b, rng, Rect{64.0, 58.0, 76.0, 72.0}, 0.92, 0.21, 0.23);
}

}  // namespace

std::vector<CampusBuilding> campus_buildings() {
  std::vector<CampusBuilding> out;
  for (const auto& t : blocks()) out.push_back(t.where);
  out.push_back(kDeck);
  return out;
}

std::vector<Climb> campus_climbs() {
  std::vector<Climb> out;
  const double run = kRisers * kTread;
  for (const auto& t : blocks())
    for (int k = 0; k + 1 < t.where.floors; ++k) {
      const Eigen::Vector3d foot = flight_foot(t.where, k);
      out.push_back({t.where.name + " stairs " + std::to_string(k) + "->" + std::to_string(k + 1),
                     {foot - Eigen::Vector3d(0, 1.4, 0), foot + Eigen::Vector3d(0, run + 1.5, 0)},
                     foot.z() + kStorey});
    }
  const double y = kDeck.footprint.y0 + kRail + kRampWidth / 2;
  out.push_back({"parking deck ramp", {{kRampFootX - 2.5, y, 0}, {kRampFootX + ramp_run() + 2.0, y, 0}}, kStorey});
  out.push_back({"lab south steps", {{11.2, 56.3, 0}, {11.2, 61.5, 0}}, kPlinth});
  out.push_back({"lab east steps", {{40.6, 67.8, 0}, {35.5, 67.8, 0}}, kPlinth});
  return out;
}

SceneInfo make_campus(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 6));
  MeshBuilder b;
  b.plane(-12, -14, 112, 112, 0.0);

  plinth(b);
  for (const auto& t : blocks()) block(b, rng, t);
  parking_deck(b, rng);
  masonry_yard(b, rng);

  // Damage: a roof slab slid down the library's east facade, another leaning on the dorm's
  // north wall; rubble heaps in the open, clear of the entrances and the avenue's middle.
  b.oriented_box({93.0, 14.0, 2.6}, {0.12, 3.0, 2.9}, 0.0, 0.45, 0.0);
  b.oriented_box({77.0, 97.0, 1.8}, {2.5, 0.12, 2.0}, 0.0, 0.0, 0.4);
  rubble_pile(b, rng, {44.0 + rng.uniform(-0.5, 0.5), 32.0}, 2.2, 16, 1.4);
  rubble_pile(b, rng, {50.0, 68.0 + rng.uniform(-0.5, 0.5)}, 2.0, 14, 1.2);
  rubble_pile(b, rng, {22.0, 91.0}, 2.5, 16, 1.5);
  rubble_pile(b, rng, {98.0, 48.0}, 1.5, 10, 1.0);
  rubble_pile(b, rng, {2.0, 50.0}, 1.8, 12, 1.1);
  // Rough ground (irregular slabs 2-7 cm high; every species crosses it) north of the library
  // and west of the dorm.
  debris_field(b, rng, Rect{64.0, 31.0, 80.0, 39.0}, 1.0, 0.02, 0.07);
  debris_field(b, rng, Rect{44.0, 84.0, 56.0, 94.0}, 1.0, 0.02, 0.07);
  // Vehicles along the streets, stones on the open ground.
  vehicle(b, {46.0, 20.0}, M_PI / 2 + rng.uniform(-0.2, 0.2));
  vehicle(b, {55.0, 62.0}, M_PI / 2 + rng.uniform(-0.2, 0.2));
  vehicle(b, {30.0, 50.0}, rng.uniform(-0.2, 0.2));
  vehicle(b, {72.0, 48.5}, rng.uniform(-0.2, 0.2));
  vehicle(b, {88.0, 35.0}, 0.1);
  vehicle(b, {96.5, 22.0}, M_PI / 2);
  vehicle(b, {40.0, 92.0}, 1.2);
  for (int i = 0; i < 12; ++i) stone(b, rng, {rng.uniform(40.0, 60.0), rng.uniform(74.0, 82.0)}, rng.uniform(0.4, 0.9));
  for (int i = 0; i < 8; ++i) stone(b, rng, {rng.uniform(82.0, 98.0), rng.uniform(40.0, 44.0)}, rng.uniform(0.4, 0.8));

  SceneInfo info;
  info.name = "campus";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -6, -0.5), Eigen::Vector3d(102, 102, 11.5));
  for (int i = 0; i < 16; ++i) info.suggested_starts.push_back({5.0 + 6.0 * i, -3.0, 0.0});
  return info;
}

}  // namespace hexplore::sim::detail
