#pragma once
// A supervoxel of the high-level map (paper "Supervoxel Data Structure"): a connected cluster
// of voxels grown from a seed on the eta_s grid, keyed globally by the seed's cell.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "common/core/coverage_gap.h"
#include "common/core/seed_key.h"

namespace hexplore::core {
struct TeamConfig;
}

namespace hexplore::highlevel {

// Values equal hexplore.v1.SurfaceClass.
enum class SurfaceClass : int { kUnspecified = 0, kGround = 1, kFacade = 2 };

// Ground and facade supervoxels may grow from the same seed cell; the facade one carries this
// bit (seed_key uses only the low 63 bits), so keys never collide across classes.
inline constexpr uint64_t kFacadeKeyBit = uint64_t{1} << 63;

inline uint64_t supervoxel_key(const core::GridCell& seed_cell, SurfaceClass surface) {
  const uint64_t key = core::seed_key(seed_cell);
  return surface == SurfaceClass::kFacade ? (key | kFacadeKeyBit) : key;
}
inline core::GridCell seed_cell_of(uint64_t supervoxel_key) {
  return core::cell_of_key(supervoxel_key & ~kFacadeKeyBit);
}
inline SurfaceClass surface_of_key(uint64_t supervoxel_key) {
  return (supervoxel_key & kFacadeKeyBit) != 0 ? SurfaceClass::kFacade : SurfaceClass::kGround;
}

struct Supervoxel {
  uint64_t key = 0;                                  // supervoxel_key(seed cell, surface)
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // mean voxel coordinate, metres
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // mean voxel normal (unit)
  bool covered = false;           // Q = 1: every voxel is a CSE (else ISE)
  int traversal_requirement = 0;  // lowest capability level with all voxels low-risk; 0 = N/A
  SurfaceClass surface = SurfaceClass::kUnspecified;
  int voxel_count = 0;
  // Incomplete supervoxels: how many voxels are complete, and the most common reason of the
  // others (ties: the lower core::CoverageGap). Covered ones: voxel_count and kNone.
  int covered_voxels = 0;
  core::CoverageGap gap = core::CoverageGap::kNone;

  bool ground() const { return surface == SurfaceClass::kGround; }
  bool facade() const { return surface == SurfaceClass::kFacade; }
  // A topology-graph vertex: ground that at least one capability level may cross.
  bool traversable() const { return ground() && traversal_requirement > 0; }
  // Species with traversal level `level` may enter (requirement <= capability, DESIGN.md §5).
  bool passable_for_level(int level) const {
    return traversable() && traversal_requirement <= level;
  }
  friend bool operator==(const Supervoxel&, const Supervoxel&) = default;
};

// The supervoxel as it travels on the radio (wire_precision.h: centre on a 1/64 m grid, normal
// in 16-bit octahedral form). Sources fuse their own contribution in this form too, so every
// robot fuses bit-identical inputs.
Supervoxel wire_rounded(Supervoxel s);

// Undirected topology edge key: the two supervoxel keys ordered so that a < b.
struct EdgeKey {
  uint64_t a = 0;
  uint64_t b = 0;
  static EdgeKey of(uint64_t x, uint64_t y) { return x < y ? EdgeKey{x, y} : EdgeKey{y, x}; }
  friend bool operator==(const EdgeKey&, const EdgeKey&) = default;
  friend auto operator<=>(const EdgeKey&, const EdgeKey&) = default;
};
struct EdgeKeyHash {
  size_t operator()(const EdgeKey& e) const noexcept {
    return std::hash<uint64_t>{}(e.a * 0x9E3779B97F4A7C15ull ^ (e.b + 0x632BE59BD9B4E019ull));
  }
};

// Traversal capability level a_zeta(k) of every species index k of the team (the order of
// core::TeamConfig::species, the bit order of low_risk_species_mask).
std::vector<int> species_levels(const core::TeamConfig& team);

// The paper's traversal requirement: the minimum level over species for which every voxel is
// low risk, given the AND of the voxels' low-risk masks; 0 (N/A) when no species qualifies.
int traversal_requirement(uint32_t all_voxels_low_risk_mask, const std::vector<int>& levels);

}  // namespace hexplore::highlevel
