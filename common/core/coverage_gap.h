#pragma once
// Why a surface element is not yet complete (paper eq. 2: Q(v) needs density, angle and
// distance at once). A voxel knows its own reason; a supervoxel carries the most common
// reason of its incomplete voxels, so that a user (and the planner) can tell surfaces that
// want more dwell time from surfaces that want another viewpoint. Values equal
// hexplore.v1.CoverageGap.

#include <cstdint>
#include <string_view>

namespace hexplore::core {

enum class CoverageGap : uint8_t {
  kNone = 0,      // complete (CSE)
  kNoNormal = 1,  // too few points around it for a surface normal: the angle is undefined
  kAngle = 2,     // never observed within the angle threshold gamma_th (grazing views only)
  kDistance = 3,  // observed at a good angle, but only from beyond the distance threshold l_th
  kDensity = 4,   // observed within both thresholds, but too few points yet (rho < rho_th)
};
inline constexpr int kCoverageGapCount = 5;

inline std::string_view to_string(CoverageGap g) {
  switch (g) {
    case CoverageGap::kNone: return "complete";
    case CoverageGap::kNoNormal: return "no_normal";
    case CoverageGap::kAngle: return "angle";
    case CoverageGap::kDistance: return "distance";
    case CoverageGap::kDensity: return "density";
  }
  return "unknown";
}

// A wire value as a gap; values this build does not know (a newer peer) read as kNone,
// "no reason given", which is also what an incomplete element from an old peer says.
inline CoverageGap coverage_gap_from_wire(uint32_t value) {
  return value < uint32_t(kCoverageGapCount) ? CoverageGap(value) : CoverageGap::kNone;
}

}  // namespace hexplore::core
