#pragma once
// Globally consistent keys for grid cells (supervoxel seeds, voxels): every robot computes the
// same key for the same integer cell, so keys associate map elements across the team.

#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace hexplore::core {

// Integer cell of a regular grid with spacing `interval_m` (floor semantics, so negative
// coordinates work and the cell boundaries are identical on every robot).
struct GridCell {
  int32_t x = 0;
  int32_t y = 0;
  int32_t z = 0;
  friend bool operator==(const GridCell&, const GridCell&) = default;
  friend auto operator<=>(const GridCell&, const GridCell&) = default;
};

inline GridCell cell_of(const Eigen::Vector3d& p, double interval_m) {
  return {static_cast<int32_t>(std::floor(p.x() / interval_m)),
          static_cast<int32_t>(std::floor(p.y() / interval_m)),
          static_cast<int32_t>(std::floor(p.z() / interval_m))};
}

inline Eigen::Vector3d cell_center(const GridCell& c, double interval_m) {
  return {(c.x + 0.5) * interval_m, (c.y + 0.5) * interval_m, (c.z + 0.5) * interval_m};
}

// A perfect (collision-free) hash of a cell: 20 bits per axis, offset to be non-negative, in
// the low 60 bits. Covers +/-524,287 cells per axis (about +/-78 km at the 0.15 m voxel size,
// +/-524 km at a 1 m seed interval). The top 4 bits are left free for users that tag a cell
// with a class (highlevel::supervoxel_key: facade bit and facing). Ordering by key is a fixed
// lexicographic order (z, y, x) that every robot agrees on.
inline constexpr int kSeedKeyAxisBits = 20;
inline constexpr int kSeedKeyCellBits = 3 * kSeedKeyAxisBits;
inline constexpr uint64_t kSeedKeyCellMask = (uint64_t{1} << kSeedKeyCellBits) - 1;
inline constexpr int64_t kSeedKeyAxisLimit = int64_t{1} << (kSeedKeyAxisBits - 1);  // |cell| < this

inline uint64_t seed_key(const GridCell& c) {
  constexpr uint64_t kMask = (uint64_t{1} << kSeedKeyAxisBits) - 1;
  auto axis = [](int32_t v) { return static_cast<uint64_t>(int64_t{v} + kSeedKeyAxisLimit) & kMask; };
  return (axis(c.z) << (2 * kSeedKeyAxisBits)) | (axis(c.y) << kSeedKeyAxisBits) | axis(c.x);
}

inline GridCell cell_of_key(uint64_t key) {
  constexpr uint64_t kMask = (uint64_t{1} << kSeedKeyAxisBits) - 1;
  auto axis = [](uint64_t bits) {
    return static_cast<int32_t>(static_cast<int64_t>(bits & kMask) - kSeedKeyAxisLimit);
  };
  return {axis(key), axis(key >> kSeedKeyAxisBits), axis(key >> (2 * kSeedKeyAxisBits))};
}

struct GridCellHash {
  size_t operator()(const GridCell& c) const noexcept { return std::hash<uint64_t>{}(seed_key(c)); }
};

}  // namespace hexplore::core
