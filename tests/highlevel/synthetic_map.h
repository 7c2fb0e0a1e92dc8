#pragma once
// Synthetic perception maps for the highlevel tests and benchmark: noisy point slabs
// voxelized like the mapping service would, and a multi-building campus of ground, walls
// and upper floors built directly as voxels.

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/voxel_sample.h"

namespace hexplore::highlevel::testing {

// Accumulates points into voxels (Gaussian mean per voxel), then emits samples.
class Voxelizer {
 public:
  explicit Voxelizer(double resolution_m) : res_(resolution_m) {}
  void add(const Eigen::Vector3d& p, uint32_t flags, uint32_t mask, const Eigen::Vector3f& normal) {
    const core::GridCell c = core::cell_of(p, res_);
    Acc& a = cells_[c];
    a.sum += p;
    a.n += 1;
    a.flags = flags;
    a.mask = mask;
    a.normal = normal;
  }
  std::vector<VoxelSample> samples() const {
    std::vector<VoxelSample> out;
    out.reserve(cells_.size());
    for (const auto& [c, a] : cells_) {
      VoxelSample s;
      s.key = c;
      s.mean = (a.sum / a.n).cast<float>();
      s.normal = a.normal;
      s.flags = a.flags;
      s.low_risk_species_mask = a.mask;
      out.push_back(s);
    }
    return out;
  }

 private:
  struct Acc {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    uint32_t flags = 0;
    uint32_t mask = 0;
    Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  };
  double res_;
  std::map<core::GridCell, Acc> cells_;
};

// Points of a horizontal slab [0,size_x) x [0,size_y) at height z with uniform +/-noise.
inline std::vector<Eigen::Vector3d> noisy_slab_points(double size_x, double size_y, double z, double noise_m,
                                                      double points_per_m2, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = static_cast<int>(size_x * size_y * points_per_m2);
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(n);
  for (int i = 0; i < n; ++i) pts.emplace_back(size_x * u(rng), size_y * u(rng), z + (2.0 * u(rng) - 1.0) * noise_m);
  return pts;
}

inline constexpr uint32_t kGroundFlags = kVoxelGround | kVoxelTraversable;

inline VoxelSample voxel_at(const core::GridCell& c, double res, uint32_t flags, uint32_t mask,
                            const Eigen::Vector3f& normal) {
  VoxelSample s;
  s.key = c;
  s.mean = Eigen::Vector3f((c.x + 0.5f) * res, (c.y + 0.5f) * res, (c.z + 0.5f) * res);
  s.normal = normal;
  s.flags = flags;
  s.low_risk_species_mask = mask;
  return s;
}

// A campus of `buildings` x `buildings` two-storey buildings on open ground: outdoor ground
// (two voxel layers where noise thickens it), building walls (facade), the ground floor and
// an upper floor slab inside each building. About 1,500 m^2 of ground for the defaults.
struct CampusSpec {
  double resolution_m = 0.15;
  double size_m = 42.0;          // square site
  int buildings = 2;             // per side
  double building_m = 9.0;       // footprint edge
  double storey_m = 3.0;
  int storeys = 2;
  uint32_t seed = 7;
};

inline std::vector<VoxelSample> campus_voxels(const CampusSpec& spec) {
  const double res = spec.resolution_m;
  const int n = static_cast<int>(spec.size_m / res);
  std::mt19937 rng(spec.seed);
  std::uniform_int_distribution<int> rough(0, 99);
  std::vector<VoxelSample> out;
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const int bcells = static_cast<int>(spec.building_m / res);
  const int gap = (n - spec.buildings * bcells) / (spec.buildings + 1);
  auto inside = [&](int ix, int iy, int* bx, int* by) {
    for (int i = 0; i < spec.buildings; ++i)
      for (int j = 0; j < spec.buildings; ++j) {
        const int x0 = gap + i * (bcells + gap);
        const int y0 = gap + j * (bcells + gap);
        if (ix >= x0 && ix < x0 + bcells && iy >= y0 && iy < y0 + bcells) {
          *bx = ix - x0;
          *by = iy - y0;
          return true;
        }
      }
    return false;
  };
  const int storey_cells = static_cast<int>(spec.storey_m / res);
  for (int ix = 0; ix < n; ++ix) {
    for (int iy = 0; iy < n; ++iy) {
      int bx = 0;
      int by = 0;
      const bool in = inside(ix, iy, &bx, &by);
      const bool wall = in && (bx == 0 || by == 0 || bx == bcells - 1 || by == bcells - 1);
      // A door in the wall facing -y of every building, 1.2 m wide and 2.1 m high.
      const bool door = wall && by == 0 && std::abs(bx - bcells / 2) <= static_cast<int>(0.6 / res);
      const int door_cells = door ? static_cast<int>(2.1 / res) : 0;
      // Rough patches only the capable species (bit 1) may cross: requirement 2.
      const uint32_t mask = ((ix / 20 + iy / 20) % 5 == 0) ? 0b10u : 0b11u;
      if (!wall || door) {
        out.push_back(voxel_at({ix, iy, 0}, res, kGroundFlags, mask, up));
        if (rough(rng) < 30) out.push_back(voxel_at({ix, iy, -1}, res, kGroundFlags, mask, up));
        if (in && !door) {
          for (int s = 1; s < spec.storeys; ++s)  // upper floor slab
            out.push_back(voxel_at({ix, iy, s * storey_cells}, res, kGroundFlags, 0b11u, up));
        }
      }
      if (wall) {
        const Eigen::Vector3f normal = (bx == 0 || bx == bcells - 1) ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
        for (int iz = door_cells; iz < spec.storeys * storey_cells; ++iz)
          out.push_back(voxel_at({ix, iy, iz}, res, 0, 0, normal));
      }
    }
  }
  return out;
}

// Overlapping voxel streams: robot i sees a band of the campus overlapping its neighbours',
// in its own order, with its own (slightly different) point means and coverage.
inline std::vector<std::vector<VoxelSample>> overlapping_streams(int robots, uint32_t seed) {
  CampusSpec spec;
  spec.size_m = 18.0;
  spec.buildings = 1;
  spec.building_m = 7.0;
  const auto all = campus_voxels(spec);
  std::vector<std::vector<VoxelSample>> streams(robots);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  const double band = spec.size_m / robots;
  for (int i = 0; i < robots; ++i) {
    for (VoxelSample v : all) {
      const double x = v.mean.x();
      if (x < (i - 0.4) * band || x > (i + 1.4) * band) continue;
      v.mean += Eigen::Vector3f(jitter(rng), jitter(rng), jitter(rng));
      if ((v.key.x + v.key.y + i) % 3 == 0) v.flags |= kVoxelCovered;
      streams[i].push_back(v);
    }
    std::shuffle(streams[i].begin(), streams[i].end(), rng);
  }
  return streams;
}

}  // namespace hexplore::highlevel::testing
