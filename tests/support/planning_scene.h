#pragma once
// A synthetic high-level map for planner tests and benchmarks (no simulator needed): flat
// ground on an eta_s grid, box buildings whose walls are facade supervoxels (with doors),
// rubble patches only capable species may cross, and a share of already covered supervoxels.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"

namespace hexplore::planning {

struct SyntheticBuilding {
  int x0, y0, x1, y1;  // footprint in cells, walls on its border, [x0, x1] x [y0, y1]
  int floors_m;        // wall height in cells
};

struct SyntheticSceneOptions {
  int width_cells = 45;   // 45 x 35 m = 1,575 m^2, about the paper's multi-building scene
  int depth_cells = 35;
  double cell_m = 1.0;    // eta_s
  std::vector<SyntheticBuilding> buildings = {{3, 3, 12, 11, 8}, {16, 4, 27, 12, 8}, {8, 18, 32, 30, 10}};
  // Rubble rectangles (traversal requirement 2), and masonry ones only a level-3 species
  // crosses (requirement 3; x0, y0, x1, y1 in cells).
  std::vector<Eigen::Vector4i> rubble = {Eigen::Vector4i(34, 2, 42, 10), Eigen::Vector4i(36, 20, 43, 32)};
  std::vector<Eigen::Vector4i> masonry;
  double covered_fraction = 0.3;  // share of supervoxels already covered (CSE)
  uint64_t seed = 7;
};

// The map as one full-snapshot update (supervoxels and 8-neighbour ground edges).
highlevel::MapUpdate synthetic_scene(const SyntheticSceneOptions& options);

// A teammate's view of `up` when it has not yet heard of part of the work: each open facade is
// seen as covered with probability `share` (a fixed draw, the same for every call).
void hide_open_facades(highlevel::MapUpdate& up, double share);

}  // namespace hexplore::planning
