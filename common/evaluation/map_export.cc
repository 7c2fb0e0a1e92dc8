#include "common/evaluation/map_export.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <octomap/OcTree.h>
#include <pcl/exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

namespace hexplore::evaluation {

Eigen::Vector3i height_colour(double z, double z_min, double z_max) {
  const double t = z_max > z_min ? std::clamp((z - z_min) / (z_max - z_min), 0.0, 1.0) : 0.0;
  // Four stops, linear in between: blue, green, yellow, red.
  static const double kStops[4][3] = {{40, 70, 220}, {40, 180, 80}, {235, 215, 40}, {215, 40, 40}};
  const double x = t * 3.0;
  const int i = std::min(2, static_cast<int>(x));
  const double f = x - i;
  Eigen::Vector3i rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = static_cast<int>(std::lround(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c])));
  return rgb;
}

std::vector<std::string> export_map(const std::vector<Eigen::Vector3f>& points, double resolution_m,
                                    const std::string& dir) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m))
    throw std::invalid_argument("export_map: resolution must be positive, got " + std::to_string(resolution_m));
  if (points.empty()) return {};
  float z_min = points.front().z(), z_max = z_min;
  for (const auto& p : points) z_min = std::min(z_min, p.z()), z_max = std::max(z_max, p.z());

  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  cloud.reserve(points.size());
  octomap::OcTree tree(resolution_m);
  for (const auto& p : points) {
    pcl::PointXYZRGB q;
    q.x = p.x(), q.y = p.y(), q.z = p.z();
    const Eigen::Vector3i rgb = height_colour(p.z(), z_min, z_max);
    q.r = static_cast<uint8_t>(rgb[0]), q.g = static_cast<uint8_t>(rgb[1]), q.b = static_cast<uint8_t>(rgb[2]);
    cloud.push_back(q);
    tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true, /*lazy_eval=*/true);
  }
  tree.updateInnerOccupancy();

  const std::filesystem::path root(dir);
  const std::string ply = (root / "map.ply").string(), pcd = (root / "map.pcd").string(), bt = (root / "map.bt").string();
  // PCL reports a failed write by a return code or by an exception, depending on the format.
  auto save = [&](const std::string& path, auto&& write) {
    try {
      if (write(path) != 0) throw std::runtime_error("cannot write " + path);
    } catch (const pcl::PCLException& e) {
      throw std::runtime_error("cannot write " + path + ": " + e.what());
    }
  };
  save(ply, [&](const std::string& p) { return pcl::io::savePLYFileBinary(p, cloud); });
  save(pcd, [&](const std::string& p) { return pcl::io::savePCDFileBinary(p, cloud); });
  if (!tree.writeBinary(bt)) throw std::runtime_error("cannot write " + bt);
  return {ply, pcd, bt};
}

std::vector<Eigen::Vector3f> load_map_points(const std::string& pcd_path) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  try {
    if (pcl::io::loadPCDFile(pcd_path, cloud) != 0) throw std::runtime_error("cannot read " + pcd_path);
  } catch (const pcl::PCLException& e) {
    throw std::runtime_error("cannot read " + pcd_path + ": " + e.what());
  }
  std::vector<Eigen::Vector3f> points;
  points.reserve(cloud.size());
  for (const auto& q : cloud) points.emplace_back(q.x, q.y, q.z);
  return points;
}

}  // namespace hexplore::evaluation
