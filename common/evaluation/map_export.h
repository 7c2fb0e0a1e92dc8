#pragma once
// The team's reconstruction in files that viewers open: the union map's occupied voxel centres
// as a point cloud coloured by height (like the paper's map figures), as binary PLY and PCD
// written with PCL (CloudCompare, MeshLab, pcl_viewer), and as an OctoMap (.bt, octovis).
// The only file of hexplore that includes PCL headers.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace hexplore::evaluation {

// Writes DIR/map.ply, DIR/map.pcd and DIR/map.bt (occupied cells of `resolution_m`) and returns
// their paths; nothing for an empty map. Throws std::runtime_error naming a file that cannot
// be written, or std::invalid_argument for a non-positive resolution.
std::vector<std::string> export_map(const std::vector<Eigen::Vector3f>& points, double resolution_m,
                                    const std::string& dir);

// The voxel centres of a map.pcd that export_map wrote (tools that read a results folder back).
// Throws std::runtime_error naming a file that cannot be read.
std::vector<Eigen::Vector3f> load_map_points(const std::string& pcd_path);

// Height colour (RGB, 0-255) of `z` on a blue (low) - green - yellow - red (high) ramp over
// [z_min, z_max].
Eigen::Vector3i height_colour(double z, double z_min, double z_max);

}  // namespace hexplore::evaluation
