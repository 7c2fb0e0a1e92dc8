#pragma once
// How far from the mission origin anything a map holds may lie. Positions that arrive from
// outside a process (a teammate's map, a mapping service's voxels) are checked against it
// before any code turns them into grid cells or fixed-point sums: a non-finite or huge
// coordinate there is undefined behaviour (found by tests/fuzz), not merely a wrong cell.

#include <cmath>

#include <Eigen/Core>

namespace hexplore::core {

// 100 km: beyond what the supervoxel keys of a 0.15 m map cover (about +/-78 km, seed_key.h),
// and small enough that a micrometre sum over ten million voxels fits in 64 bits.
inline constexpr double kMaxWorldCoordinateM = 1.0e5;

template <typename Derived>
bool within_world(const Eigen::MatrixBase<Derived>& p) {
  return p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxWorldCoordinateM;
}

// A unit normal as the wire carries it (rounded to float), or none (zero). Anything longer,
// or not finite, is malformed.
template <typename Derived>
bool plausible_normal(const Eigen::MatrixBase<Derived>& n) {
  return n.allFinite() && n.squaredNorm() <= 1.5;
}

}  // namespace hexplore::core
