#include "common/sim/ground_truth.h"

#include <algorithm>
#include <cmath>

#include "common/core/rng.h"

namespace hexplore::sim {

SurfaceSamples sample_surface(const TriangleMesh& mesh, double spacing_m, uint64_t seed,
                              const Eigen::AlignedBox3d* crop) {
  SurfaceSamples out;
  out.spacing_m = spacing_m;
  core::SimRng rng(core::sim_seed(seed, 0x5A3D));
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

namespace {

// The occupied voxels of a map as one bit per cell over the samples' bounding box (one cell of
// margin): the station evaluates ~10^6 samples x 27 neighbours per snapshot, and a bit test is
// an order of magnitude cheaper than a hash look-up. Voxels outside the box are no sample's
// neighbour and are left out.
class DenseOccupancy {
 public:
  // Cells above this many fall back to VoxelSet::near (a scene of several km^2).
  static constexpr size_t kMaxCells = size_t{1} << 31;

  DenseOccupancy(const std::vector<core::GridCell>& sample_cells, const VoxelSet& map) {
    if (sample_cells.empty()) return;
    lo_ = hi_ = sample_cells.front();
    for (const auto& c : sample_cells) {
      lo_ = {std::min(lo_.x, c.x), std::min(lo_.y, c.y), std::min(lo_.z, c.z)};
      hi_ = {std::max(hi_.x, c.x), std::max(hi_.y, c.y), std::max(hi_.z, c.z)};
    }
    lo_ = {lo_.x - 1, lo_.y - 1, lo_.z - 1};
    hi_ = {hi_.x + 1, hi_.y + 1, hi_.z + 1};
    nx_ = size_t(hi_.x - lo_.x + 1);
    ny_ = size_t(hi_.y - lo_.y + 1);
    const size_t cells = nx_ * ny_ * size_t(hi_.z - lo_.z + 1);
    if (cells > kMaxCells) return;
    bits_.assign(cells, false);
    map.for_each_cell([this](const core::GridCell& c) {
      if (inside(c)) bits_[index(c)] = true;
    });
    usable_ = true;
  }
  bool usable() const { return usable_; }
  // The sample's cell is inside the box with its margin, so every neighbour is too.
  bool near(const core::GridCell& c) const {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (bits_[index({c.x + dx, c.y + dy, c.z + dz})]) return true;
    return false;
  }

 private:
  bool inside(const core::GridCell& c) const {
    return c.x >= lo_.x && c.y >= lo_.y && c.z >= lo_.z && c.x <= hi_.x && c.y <= hi_.y && c.z <= hi_.z;
  }
  size_t index(const core::GridCell& c) const {
    return (size_t(c.z - lo_.z) * ny_ + size_t(c.y - lo_.y)) * nx_ + size_t(c.x - lo_.x);
  }
  core::GridCell lo_, hi_;
  size_t nx_ = 0, ny_ = 0;
  std::vector<bool> bits_;
  bool usable_ = false;
};

}  // namespace

Completeness completeness(const SurfaceSamples& samples, const VoxelSet& map, const std::vector<uint8_t>* mask) {
  Completeness r;
  std::vector<size_t> counted;
  std::vector<core::GridCell> cells;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    if (mask && (i >= mask->size() || !(*mask)[i])) continue;
    counted.push_back(i);
    cells.push_back(core::cell_of(samples.points[i].cast<double>(), map.resolution_m()));
  }
  r.total = counted.size();
  if (map.size() > 0) {
    const DenseOccupancy dense(cells, map);
    for (size_t k = 0; k < counted.size(); ++k)
      if (dense.usable() ? dense.near(cells[k]) : map.near(samples.points[counted[k]])) ++r.covered;
  }
  r.fraction = r.total ? static_cast<double>(r.covered) / static_cast<double>(r.total) : 0.0;
  return r;
}

}  // namespace hexplore::sim
