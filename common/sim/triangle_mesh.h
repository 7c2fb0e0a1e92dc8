#pragma once
// An indexed triangle soup in the world frame (metres, z up): the ground truth every
// simulator part works from. Winding is not assumed consistent; consumers treat faces as
// two-sided.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hexplore::sim {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  bool empty() const { return triangles.empty(); }
  size_t triangle_count() const { return triangles.size(); }

  // Appends another mesh (indices re-based).
  void append(const TriangleMesh& other);
  // Applies x <- T x to every vertex.
  void transform(const Eigen::Affine3f& t);
  // Removes triangles with (near) zero area and vertices no triangle uses.
  void drop_degenerate(float min_area_m2 = 1e-10f);

  Eigen::AlignedBox3f bounds() const;
  double surface_area() const;
  double triangle_area(size_t i) const;
  // FNV-1a over the vertex and index buffers: equal for bit-identical meshes.
  uint64_t content_hash() const;
};

}  // namespace hexplore::sim
