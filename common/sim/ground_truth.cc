#include "common/sim/ground_truth.h"

#include <cmath>

#include "common/sim/rng.h"

namespace hexplore::sim {

SurfaceSamples sample_surface(const TriangleMesh& mesh, double spacing_m, uint64_t seed,
                              const Eigen::AlignedBox3d* crop) {
  SurfaceSamples out;
  out.spacing_m = spacing_m;
  Rng rng(mix_seed(seed, 0x5A3D));
  const double per_m2 = 1.0 / (spacing_m * spacing_m);
  out.points.reserve(static_cast<size_t>(mesh.surface_area() * per_m2 * 1.05) + 16);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const double expected = mesh.triangle_area(i) * per_m2;
    // Stochastic rounding keeps small triangles represented in proportion to their area.
    const auto n = static_cast<size_t>(std::floor(expected + rng.uniform()));
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>(), b = mesh.vertices[t[1]].cast<double>(),
                          c = mesh.vertices[t[2]].cast<double>();
    for (size_t k = 0; k < n; ++k) {
      double u = rng.uniform(), v = rng.uniform();
      if (u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      const Eigen::Vector3d p = a + u * (b - a) + v * (c - a);
      if (crop && !crop->contains(p)) continue;
      out.points.push_back(p.cast<float>());
    }
  }
  return out;
}

VoxelSet VoxelSet::from_keys(double resolution_m, std::span<const int32_t> keys_xyz) {
  VoxelSet s(resolution_m);
  s.keys_.reserve(keys_xyz.size() / 3);
  for (size_t i = 0; i + 2 < keys_xyz.size(); i += 3) s.insert({keys_xyz[i], keys_xyz[i + 1], keys_xyz[i + 2]});
  return s;
}

VoxelSet VoxelSet::from_points(double resolution_m, std::span<const Eigen::Vector3f> points) {
  VoxelSet s(resolution_m);
  s.keys_.reserve(points.size());
  for (const auto& p : points) s.insert(core::cell_of(p.cast<double>(), resolution_m));
  return s;
}

bool VoxelSet::near(const Eigen::Vector3f& p) const {
  const core::GridCell c = core::cell_of(p.cast<double>(), resolution_m_);
  if (contains(c)) return true;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (contains({c.x + dx, c.y + dy, c.z + dz})) return true;
  return false;
}

Completeness completeness(const SurfaceSamples& samples, const VoxelSet& map, const std::vector<uint8_t>* mask) {
  Completeness r;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    if (mask && (i >= mask->size() || !(*mask)[i])) continue;
    ++r.total;
    if (map.size() > 0 && map.near(samples.points[i])) ++r.covered;
  }
  r.fraction = r.total ? static_cast<double>(r.covered) / static_cast<double>(r.total) : 0.0;
  return r;
}

}  // namespace hexplore::sim
