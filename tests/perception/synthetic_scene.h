#pragma once
// Analytic point clouds for perception tests: dense samplings of planar patches whose terrain
// and observation answers are known in advance.

#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/core/team_config.h"
#include "common/perception/perception_map.h"

namespace hexplore::perception::testing {

// Points origin + a*u + b*v on a grid of `spacing` metres over a, b in [0, 1].
inline void add_patch(std::vector<float>& out, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                      const Eigen::Vector3d& v, double spacing) {
  const int nu = std::max(1, static_cast<int>(std::lround(u.norm() / spacing)));
  const int nv = std::max(1, static_cast<int>(std::lround(v.norm() / spacing)));
  for (int i = 0; i <= nu; ++i) {
    for (int j = 0; j <= nv; ++j) {
      const Eigen::Vector3d p = origin + u * (static_cast<double>(i) / nu) + v * (static_cast<double>(j) / nv);
      out.push_back(static_cast<float>(p.x()));
      out.push_back(static_cast<float>(p.y()));
      out.push_back(static_cast<float>(p.z()));
    }
  }
}

// Horizontal rectangle [x0,x1] x [y0,y1] at height z.
inline void add_floor(std::vector<float>& out, double x0, double x1, double y0, double y1, double z, double spacing) {
  add_patch(out, {x0, y0, z}, {x1 - x0, 0, 0}, {0, y1 - y0, 0}, spacing);
}

inline ScanPoints scan_of(const std::vector<float>& pts, const Eigen::Vector3d& sensor) {
  ScanPoints s;
  s.sensor_origin = sensor;
  s.xyz = pts.data();
  s.count = pts.size() / 3;
  return s;
}

// Team of the paper's two species: index 0 = SLUGCAT (tracked), 1 = MR1000 (wheeled).
inline MapParams two_species_params(const core::SpeciesConfig& own = core::builtin_slugcat()) {
  return make_map_params(core::AlgorithmParams{}, {core::builtin_slugcat(), core::builtin_mr1000()}, own);
}
inline constexpr uint32_t kSlugcatBit = 1;
inline constexpr uint32_t kMr1000Bit = 2;

inline uint64_t pack(const core::GridCell& k) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(k.x)) & 0xFFFFF) |
         ((static_cast<uint64_t>(static_cast<uint32_t>(k.y)) & 0xFFFFF) << 20) |
         ((static_cast<uint64_t>(static_cast<uint32_t>(k.z)) & 0xFFFFF) << 40);
}

// Whether `to` is reachable from `from` over voxels low-risk for `species_bit`, 26-connected.
inline bool reachable(const PerceptionMap& map, const core::GridCell& from, const core::GridCell& to, uint32_t species_bit) {
  std::unordered_set<uint64_t> passable;
  for (const VoxelView& v : map.voxels()) {
    if ((v.low_risk_species_mask & species_bit) != 0) passable.insert(pack(v.key));
  }
  if (!passable.count(pack(from)) || !passable.count(pack(to))) return false;
  std::unordered_set<uint64_t> seen{pack(from)};
  std::vector<core::GridCell> stack{from};
  while (!stack.empty()) {
    const core::GridCell k = stack.back();
    stack.pop_back();
    if (k == to) return true;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const core::GridCell n{k.x + dx, k.y + dy, k.z + dz};
          if (passable.count(pack(n)) && seen.insert(pack(n)).second) stack.push_back(n);
        }
  }
  return false;
}

}  // namespace hexplore::perception::testing
