#pragma once
// A supervoxel of the high-level map (paper "Supervoxel Data Structure"): a connected cluster
// of voxels grown from a seed on the eta_s grid, keyed globally by the seed's cell.

#include <algorithm>
#include <cmath>
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

// Which way a facade surface faces: the axis its outward (sensor-side) normal is closest to.
// The paper's segmentation follows the 3D boundaries of objects: the outer and inner faces of
// a wall, and a floor and the ceiling under it, are different supervoxels. One eta_s cell of a
// building's wall holds the outer face, the inner face seen through a window, the window's
// reveals, sill and lintel; averaged into one supervoxel, their normals give a direction none
// of them has, a view made for it sees half of them, and the supervoxel never completes.
// kNone: a voxel without a normal.
enum class Facing : uint8_t { kNone = 0, kPlusX = 1, kMinusX = 2, kPlusY = 3, kMinusY = 4, kUp = 5, kDown = 6 };
inline constexpr int kFacingCount = 7;

// The facing of a (sensor-oriented) voxel normal: up or down when it is steeper than 45 deg,
// else the horizontal axis it is closest to. Ties go to the first in enum order.
inline Facing facing_of(const Eigen::Vector3f& n) {
  const float ax = std::abs(n.x()), ay = std::abs(n.y()), az = std::abs(n.z());
  if (ax == 0.0f && ay == 0.0f && az == 0.0f) return Facing::kNone;
  if (az * az >= ax * ax + ay * ay) return n.z() > 0 ? Facing::kUp : Facing::kDown;
  if (ax >= ay) return n.x() >= 0 ? Facing::kPlusX : Facing::kMinusX;
  return n.y() >= 0 ? Facing::kPlusY : Facing::kMinusY;
}

// Supervoxel keys: the seed cell's core::seed_key in the low 60 bits, the facing in bits 60-62
// and the facade bit 63. Ground and facade supervoxels (of every facing) may grow from the same
// seed cell, so keys never collide across classes; a ground key is the plain seed_key.
inline constexpr uint64_t kFacadeKeyBit = uint64_t{1} << 63;
inline constexpr int kFacingKeyShift = core::kSeedKeyCellBits;
inline constexpr uint64_t kClassKeyMask = ~core::kSeedKeyCellMask;  // facade bit and facing

inline uint64_t supervoxel_key(const core::GridCell& seed_cell, SurfaceClass surface, Facing facing = Facing::kNone) {
  const uint64_t key = core::seed_key(seed_cell);
  if (surface != SurfaceClass::kFacade) return key;
  return key | kFacadeKeyBit | (uint64_t(facing) << kFacingKeyShift);
}
inline core::GridCell seed_cell_of(uint64_t supervoxel_key) {
  return core::cell_of_key(supervoxel_key & core::kSeedKeyCellMask);
}
inline SurfaceClass surface_of_key(uint64_t supervoxel_key) {
  return (supervoxel_key & kFacadeKeyBit) != 0 ? SurfaceClass::kFacade : SurfaceClass::kGround;
}
inline Facing facing_of_key(uint64_t supervoxel_key) {
  return Facing((supervoxel_key >> kFacingKeyShift) & 7);
}

struct Supervoxel {
  uint64_t key = 0;                                  // supervoxel_key(seed cell, surface, facing)
  // Mean voxel coordinate (metres) and mean voxel normal (unit); of the incomplete voxels only
  // while an incomplete facade (supervoxel_stats.h: the paper's ISE supervoxel).
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
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
