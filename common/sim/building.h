#pragma once
// Building parts for the procedural scenes: walls with door and window openings, floor
// slabs with stairwell holes, and whole multi-floor shells. All axis-aligned, metres.

#include <vector>

#include <Eigen/Core>

#include "common/sim/mesh_builder.h"

namespace hexplore::sim {

struct Rect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(double x, double y) const { return x > x0 && x < x1 && y > y0 && y < y1; }
};

// A hole through a wall: [from, to] along the wall from its start point, [bottom, top]
// above the wall's base.
struct Opening {
  double from = 0, to = 0, bottom = 0, top = 0;
};

// Wall of `thickness` centred on the axis-aligned segment a-b, from base_z up `height`.
void add_wall(MeshBuilder& b, const Eigen::Vector2d& a, const Eigen::Vector2d& end, double thickness, double base_z,
              double height, std::vector<Opening> openings);

// Horizontal slab over `outline` between z_bottom and z_top, minus `holes`.
void add_slab(MeshBuilder& b, const Rect& outline, double z_bottom, double z_top, const std::vector<Rect>& holes);

enum class Side { kSouth, kNorth, kWest, kEast };

// A multi-floor shell: exterior walls (doors on the ground floor, windows on every floor),
// one slab per upper floor and a roof. Floor k's walking surface is at z = base_z + k * floor_height.
struct BuildingSpec {
  struct Door {
    Side side = Side::kSouth;
    double offset_m = 1.0;   // from the footprint corner with the smaller coordinate
    double width_m = 1.4;
    double height_m = 2.2;
  };
  Rect footprint;
  double base_z_m = 0.0;  // ground floor level (above 0 for a building on a plinth)
  int floors = 1;
  double floor_height_m = 3.5;
  double wall_m = 0.25;
  double slab_m = 0.2;
  std::vector<Door> doors;
  double window_spacing_m = 3.0;
  double window_width_m = 1.2;
  double window_sill_m = 1.0;
  double window_height_m = 1.2;
  // Holes (stairwells) per slab: holes[k] applies to the slab under floor k + 1.
  std::vector<std::vector<Rect>> slab_holes;
  bool roof = true;
};

// A guard wall `height` tall standing on the slab at `base_z` around the hole `hole`, on the
// slab side of its edges, except along the sides listed in `open` (where a ramp or a stair
// comes up). Keeps robots on an upper floor from driving into a stairwell, ramp or atrium.
void add_parapet(MeshBuilder& b, const Rect& hole, double base_z, double height, double thickness,
                 const std::vector<Side>& open = {});

// Throws SceneError for a door smaller than kMinDoorWidthM x kMinDoorHeightM.
void add_building(MeshBuilder& b, const BuildingSpec& spec);

// Doors wide and tall enough for every robot species (the tests check this).
constexpr double kMinDoorWidthM = 1.2;
constexpr double kMinDoorHeightM = 2.0;

}  // namespace hexplore::sim
