// office: a one-storey office floor of 40 m x 19.5 m (x in [0, 40], y in [0, 19.5], ceiling
// 2.8 m under a roof slab): two long corridors along x (C1 at y in [4, 6], C2 at y in
// [13.5, 15.5], 1.85 m clear) joined by three cross corridors (X1 in the middle, x in
// [19, 21], from the south to the north entrance; X2 and X3 at the west and east ends), and
// four rows of small dead-end rooms (2.3-4.5 m wide, 3.6-3.75 m deep) whose only door is a
// 0.90-1.00 m gap in the corridor wall: wide enough for the wheeled MR1000 (0.70 m) only when
// it drives straight through, too narrow for it to turn in. Desks and cabinets stand against
// room walls, bins and printers against corridor walls, away from the doors. Exterior doors
// (1.6 m) open X1 to the south and north, C1 to the west and C2 to the east. Room widths, door
// widths and positions and the furniture follow the seed. Robots start south of the building.
#include "common/sim/scene_parts.h"

#include <algorithm>

namespace hexplore::sim::detail {
namespace {

constexpr double kWall = 0.25;       // exterior
constexpr double kPartition = 0.15;  // interior walls
constexpr double kStorey = 3.0;
constexpr double kSlab = 0.2;
constexpr double kWallHeight = kStorey - kSlab;
constexpr double kDoorHeight = 2.1;

// One row of rooms: interior y range, the corridor wall line its doors are in, and the x
// spans it covers (split by the cross corridors).
struct Row {
  double y0, y1;
  double door_wall_y;
  std::vector<std::pair<double, double>> spans;
};

const Row kRows[] = {
    {kWall, 4.0 - kPartition / 2, 4.0, {{kWall, 19.0}, {21.0, 40.0 - kWall}}},                       // S1
    {6.0 + kPartition / 2, 9.75 - kPartition / 2, 6.0, {{2.25, 19.0}, {21.0, 37.75}}},               // N1
    {9.75 + kPartition / 2, 13.5 - kPartition / 2, 13.5, {{2.25, 19.0}, {21.0, 37.75}}},             // S2
    {15.5 + kPartition / 2, 19.5 - kWall, 15.5, {{kWall, 19.0}, {21.0, 40.0 - kWall}}},              // N2
};

}  // namespace

OfficeLayout office_layout(uint64_t seed) {
  core::SimRng rng(core::sim_seed(seed, 4));
  OfficeLayout out;
  out.footprint = {0, 0, 40, 19.5};
  out.corridors = {{kWall, 4.0 + kPartition / 2, 40 - kWall, 6.0 - kPartition / 2},
                   {kWall, 13.5 + kPartition / 2, 40 - kWall, 15.5 - kPartition / 2},
                   {19.0 + kPartition / 2, kWall, 21.0 - kPartition / 2, 19.5 - kWall},
                   {kWall, 6.0, 2.25 - kPartition / 2, 13.5},
                   {37.75 + kPartition / 2, 6.0, 40 - kWall, 13.5}};
  for (const Row& row : kRows)
    for (const auto& [x_begin, x_end] : row.spans) {
      // Room boundaries: widths of 3.0-4.5 m while more than two rooms' worth is left, then
      // the rest as one room, or two equal ones (2.25-3.75 m) when it is wider than 4.5 m.
      std::vector<double> cuts = {x_begin};
      while (x_end - cuts.back() > 7.5) cuts.push_back(cuts.back() + rng.uniform(3.0, 4.5));
      if (x_end - cuts.back() > 4.5) cuts.push_back(0.5 * (cuts.back() + x_end));
      cuts.push_back(x_end);
      for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        OfficeRoom room;
        // Partitions stand on the cuts; the span ends are walls already (exterior, cross corridor).
        const double x0 = i == 0 ? cuts[i] + (x_begin == kWall ? 0 : kPartition / 2) : cuts[i] + kPartition / 2;
        const double x1 = i + 2 == cuts.size() ? cuts[i + 1] - (x_end == 40 - kWall ? 0 : kPartition / 2)
                                               : cuts[i + 1] - kPartition / 2;
        room.interior = {x0, row.y0, x1, row.y1};
        room.door_width_m = rng.uniform(0.90, 1.00);
        const double margin = 0.3 + room.door_width_m / 2;  // keeps a door clear of the partitions
        const double centre = rng.uniform(x0 + margin, x1 - margin);
        room.door = {centre - room.door_width_m / 2, row.door_wall_y - kPartition / 2, centre + room.door_width_m / 2,
                     row.door_wall_y + kPartition / 2};
        room.door_faces_north = row.door_wall_y > row.y1;
        out.rooms.push_back(room);
      }
    }
  return out;
}

SceneInfo make_office(uint64_t seed) {
  const OfficeLayout layout = office_layout(seed);
  core::SimRng rng(core::sim_seed(seed, 14));
  MeshBuilder b;
  b.plane(-8, -10, 48, 28, 0.0);

  BuildingSpec shell;
  shell.footprint = layout.footprint;
  shell.floors = 1;
  shell.floor_height_m = kStorey;
  shell.wall_m = kWall;
  shell.slab_m = kSlab;
  shell.doors = {{Side::kSouth, 19.2, 1.6, 2.2}, {Side::kNorth, 19.2, 1.6, 2.2}, {Side::kWest, 4.2, 1.6, 2.2},
                 {Side::kEast, 13.7, 1.6, 2.2}};
  add_building(b, shell);

  // Corridor walls along x, per row and span, with the rows' doors.
  for (const Row& row : kRows)
    for (const auto& [x_begin, x_end] : row.spans) {
      std::vector<Opening> doors;
      for (const auto& room : layout.rooms)
        if (room.door.y0 < row.door_wall_y && room.door.y1 > row.door_wall_y && room.door.x0 > x_begin &&
            room.door.x1 < x_end)
          doors.push_back({room.door.x0 - x_begin, room.door.x1 - x_begin, 0.0, kDoorHeight});
      add_wall(b, {x_begin, row.door_wall_y}, {x_end, row.door_wall_y}, kPartition, 0.0, kWallHeight, doors);
    }
  // The wall between the back-to-back rows N1 and S2; the cross corridors' walls.
  for (const auto& [x0, x1] : kRows[1].spans) add_wall(b, {x0, 9.75}, {x1, 9.75}, kPartition, 0.0, kWallHeight, {});
  for (double x : {19.0, 21.0}) {
    add_wall(b, {x, kWall}, {x, 4.0}, kPartition, 0.0, kWallHeight, {});
    add_wall(b, {x, 6.0}, {x, 13.5}, kPartition, 0.0, kWallHeight, {});
    add_wall(b, {x, 15.5}, {x, 19.5 - kWall}, kPartition, 0.0, kWallHeight, {});
  }
  add_wall(b, {2.25, 6.0}, {2.25, 13.5}, kPartition, 0.0, kWallHeight, {});
  add_wall(b, {37.75, 6.0}, {37.75, 13.5}, kPartition, 0.0, kWallHeight, {});

  // Partitions between neighbouring rooms of a row, and the rooms' furniture: a desk against
  // the back wall, a cabinet against a side wall in the back half (never in front of the door).
  for (size_t i = 0; i < layout.rooms.size(); ++i) {
    const OfficeRoom& r = layout.rooms[i];
    const Rect& f = r.interior;
    if (i + 1 < layout.rooms.size() && layout.rooms[i + 1].interior.y0 == f.y0 &&
        std::abs(layout.rooms[i + 1].interior.x0 - f.x1 - kPartition) < 1e-6) {
      const double x = f.x1 + kPartition / 2;
      add_wall(b, {x, f.y0}, {x, f.y1}, kPartition, 0.0, kWallHeight, {});
    }
    const double back = r.door_faces_north ? f.y0 : f.y1;   // wall opposite the door
    const double inward = r.door_faces_north ? 1.0 : -1.0;  // from the back wall into the room
    if (rng.chance(0.7)) {
      const double w = std::min(1.4, f.x1 - f.x0 - 0.4), cx = rng.uniform(f.x0 + 0.1 + w / 2, f.x1 - 0.1 - w / 2);
      const double y_a = back + inward * 0.02, y_b = back + inward * 0.72;
      b.box({cx - w / 2, std::min(y_a, y_b), 0.0}, {cx + w / 2, std::max(y_a, y_b), 0.75});
    }
    if (rng.chance(0.4)) {
      const bool west = rng.chance(0.5);
      const double x_a = west ? f.x0 + 0.02 : f.x1 - 0.47, x_b = x_a + 0.45;
      const double y_mid = 0.5 * (f.y0 + f.y1);
      const double y_a = r.door_faces_north ? y_mid - 0.9 : y_mid, y_b = y_a + 0.9;
      b.box({x_a, y_a, 0.0}, {x_b, y_b, 1.8});
    }
  }

  // Corridor clutter: bins and printers against the long corridors' walls, clear of doors and
  // of the cross-corridor junctions.
  for (int i = 0, placed = 0; i < 40 && placed < 6; ++i) {
    const bool c2 = placed % 2 == 1, north = rng.chance(0.5);
    const double len = rng.uniform(0.5, 0.9), depth = rng.uniform(0.4, 0.55), h = rng.uniform(0.9, 1.3);
    const double x = rng.uniform(3.0, 37.0);
    const double wall_y = c2 ? (north ? 15.5 : 13.5) : (north ? 6.0 : 4.0);
    bool clear = std::abs(x - 20.0) > 2.0;
    for (const auto& r : layout.rooms)
      if (r.door.y0 < wall_y && r.door.y1 > wall_y) clear = clear && (x + len / 2 < r.door.x0 - 0.8 || x - len / 2 > r.door.x1 + 0.8);
    if (!clear) continue;
    const double face = wall_y + (north ? -kPartition / 2 : kPartition / 2);
    const double y_a = face + (north ? -depth : 0.0);
    b.box({x - len / 2, y_a, 0.0}, {x + len / 2, y_a + depth, h});
    ++placed;
  }

  SceneInfo info;
  info.name = "office";
  info.mesh = b.take();
  info.site = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -5, -0.5), Eigen::Vector3d(42, 21.5, 3.5));
  info.suggested_starts = {{16, -3, 0}, {18, -3, 0}, {22, -3, 0}, {24, -3, 0}};
  return info;
}

}  // namespace hexplore::sim::detail
