#pragma once
// The payload of one leaf voxel of the perception octree: the Gaussian of the points that fell
// in it, the observation metrics, the cached terrain metrics and the last published state.
// Packed into 64 bytes (floats and quantized fields) because a building map holds millions.

#include <cmath>
#include <cstdint>

namespace hexplore::perception {

// Bits of VoxelData::flags. The low three match hexplore.v1.VoxelFlag.
inline constexpr uint8_t kFlagGround = 1;
inline constexpr uint8_t kFlagCovered = 2;
inline constexpr uint8_t kFlagTraversable = 4;
inline constexpr uint8_t kPublishedFlagsMask = kFlagGround | kFlagCovered | kFlagTraversable;
// Internal bits, never published.
inline constexpr uint8_t kFlagScratchTouched = 0x08;  // scan-local: this scan hit it
inline constexpr uint8_t kFlagChangePending = 0x10;  // in the change list
inline constexpr uint8_t kFlagWasPublished = 0x20;   // pub_* hold the last published state
inline constexpr uint8_t kFlagScratchGeometry = 0x40;  // scan-local set membership
inline constexpr uint8_t kFlagScratchRisk = 0x80;

inline constexpr uint16_t kNoObservation = 0xFFFF;

struct VoxelData {
  // Gaussian moments of the points relative to the voxel centre, which keeps float sums exact
  // enough (offsets are below half a voxel) anywhere in a multi-kilometre map.
  float sum[3] = {0.f, 0.f, 0.f};
  float sum_sq[6] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f};  // xx xy xz yy yz zz
  uint16_t count = 0;  // points in the voxel; halved with the moments past 2^15
  // Points per cm^2 of the surface fitted to the voxel's 3x3x3 neighbourhood, in 0.001 units
  // (MapParams::Density::kFusedSurface), saturating; refreshed with the normal.
  uint16_t fused_density_q = 0;
  int16_t normal_q[3] = {0, 0, 0};            // unit normal * 32767; all zero: no normal yet
  // Minimum angle and distance of the qualifying observations (both thresholds met); while
  // none qualified (obs_points == 0), the minima of the failed ones, which tell the coverage
  // gap (angle or distance, core::CoverageGap).
  uint16_t obs_angle_cdeg = kNoObservation;    // 0.01 deg
  uint16_t obs_distance_cm = kNoObservation;   // cm
  uint16_t obs_points = 0;                     // points of qualifying observations (saturating)
  uint32_t low_risk_mask = 0;                  // bit k: R_k(v) = 0
  uint8_t empty_neighbours : 5 = 26;           // of the 26 neighbour cells
  uint8_t pub_gap : 3 = 0;                     // last published core::CoverageGap
  uint8_t flags = 0;
  int8_t pub_mean_q[3] = {0, 0, 0};            // last published mean offset, resolution / 254
  int8_t pub_normal_q[3] = {0, 0, 0};          // last published normal * 127

  bool operator==(const VoxelData&) const = default;

  bool has_normal() const { return normal_q[0] != 0 || normal_q[1] != 0 || normal_q[2] != 0; }
  void normal(float out[3]) const {
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(normal_q[i]) / 32767.f;
  }
  void set_normal(double x, double y, double z) {
    normal_q[0] = static_cast<int16_t>(std::lround(x * 32767.0));
    normal_q[1] = static_cast<int16_t>(std::lround(y * 32767.0));
    normal_q[2] = static_cast<int16_t>(std::lround(z * 32767.0));
  }
  bool has_observation() const { return obs_points > 0; }
};

static_assert(sizeof(VoxelData) == 64, "VoxelData is laid out to fill exactly 64 bytes");

}  // namespace hexplore::perception
