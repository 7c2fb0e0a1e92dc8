#include "common/sim/triangle_mesh.h"

#include <cstring>

namespace hexplore::sim {

void TriangleMesh::append(const TriangleMesh& other) {
  const auto base = static_cast<uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void TriangleMesh::transform(const Eigen::Affine3f& t) {
  for (auto& v : vertices) v = t * v;
}

void TriangleMesh::drop_degenerate(float min_area_m2) {
  std::vector<std::array<uint32_t, 3>> kept;
  kept.reserve(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i)
    if (triangle_area(i) > min_area_m2) kept.push_back(triangles[i]);
  std::vector<int64_t> remap(vertices.size(), -1);
  std::vector<Eigen::Vector3f> used;
  for (auto& t : kept)
    for (auto& idx : t) {
      if (remap[idx] < 0) {
        remap[idx] = static_cast<int64_t>(used.size());
        used.push_back(vertices[idx]);
      }
      idx = static_cast<uint32_t>(remap[idx]);
    }
  vertices = std::move(used);
  triangles = std::move(kept);
}

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& t : triangles)
    for (auto idx : t) box.extend(vertices[idx]);
  return box;
}

double TriangleMesh::triangle_area(size_t i) const {
  const auto& t = triangles[i];
  const Eigen::Vector3d a = vertices[t[0]].cast<double>();
  const Eigen::Vector3d b = vertices[t[1]].cast<double>();
  const Eigen::Vector3d c = vertices[t[2]].cast<double>();
  return 0.5 * (b - a).cross(c - a).norm();
}

double TriangleMesh::surface_area() const {
  double sum = 0.0;
  for (size_t i = 0; i < triangles.size(); ++i) sum += triangle_area(i);
  return sum;
}

uint64_t TriangleMesh::content_hash() const {
  uint64_t h = 1469598103934665603ull;
  auto feed = [&h](const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) {
      h ^= p[i];
      h *= 1099511628211ull;
    }
  };
  for (const auto& v : vertices) feed(v.data(), sizeof(float) * 3);
  for (const auto& t : triangles) feed(t.data(), sizeof(uint32_t) * 3);
  return h;
}

}  // namespace hexplore::sim
