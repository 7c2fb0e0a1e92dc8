#pragma once
// Terrain metrics of one voxel (paper: normal n(v), slope s(v), sparsity d(v) from the fused
// Gaussians of its 3x3x3 neighbourhood) and its boolean traversal risk R_k(v) per species.

#include <cstdint>

#include <Eigen/Core>
#include <octomap/OcTreeKey.h>

#include "common/perception/map_params.h"
#include "common/perception/neighbour_lookup.h"
#include "common/perception/voxel_data.h"

namespace hexplore::perception {

// Grid extents the risk evaluation looks at, derived once from the species limits.
struct TerrainWindow {
  int step_cells = 3;       // neighbour columns are searched +-step_cells around the voxel
  int clearance_cells = 6;  // cells above the voxel checked for overhead obstacles
  static TerrainWindow from(const MapParams& params);
};

// Slope in degrees of a unit normal against the vertical: 0 = floor, 90 = wall, 180 = ceiling.
double slope_deg(const float normal[3]);

// World position of the Gaussian mean of `d`, a voxel whose centre is `centre`.
Eigen::Vector3d voxel_mean(const VoxelData& d, const Eigen::Vector3d& centre);

// Recomputes the normal and the empty-neighbour count of the voxel at `key` from the fused
// Gaussian of its 3x3x3 neighbourhood. The normal is the eigenvector of the smallest eigenvalue,
// oriented (when the voxel had none, or when `orient_to_sensor` and the plane is shallow or
// `sensor` within gamma_th of it) towards `sensor`, or up when the plane is shallower than s_th
// and the sensor above it; a new steep plane seen at a grazing angle faces the side `sensor`
// sees of the voxel's own points when they are planar. Otherwise the normal keeps the side of
// the previous one. A neighbourhood with too few points, or points on a line only, leaves the
// previous normal.
void update_geometry(const octomap::OcTreeKey& key, VoxelData& d, NeighbourLookup& lookup,
                     const Eigen::Vector3d& centre, const Eigen::Vector3d& sensor, bool orient_to_sensor,
                     const MapParams& params);

// Terrain quantities behind R_k(v) for a ground voxel.
struct TerrainSample {
  double slope_deg = 180.0;
  double sparsity = 1.0;            // empty neighbour cells / 26
  double step_m = 0.0;              // largest height change to a neighbouring column's surface
  double roughness_m = 0.0;         // RMS residual of a plane through the 3x3 column heights
  double clearance_m = 1.0e9;       // free height above the surface to the first overhead voxel
};


TerrainSample sample_terrain(const octomap::OcTreeKey& key, const VoxelData& d, NeighbourLookup& lookup,
                             const Eigen::Vector3d& centre, const TerrainWindow& window, const MapParams& params);

// Bit k set when species k of params.species sees the sample as low risk (R_k(v) = 0).
uint32_t low_risk_mask(const TerrainSample& t, const MapParams& params);

}  // namespace hexplore::perception
