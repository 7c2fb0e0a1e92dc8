#pragma once
// The precision at which supervoxels travel on the team radio (common/radio/map_codec): centres
// on a 1/64 m grid (a tenth of the 0.15 m map resolution; an exact binary fraction, so the grid
// value is the same double everywhere) and unit normals in 16-bit octahedral form (about 0.6
// degrees). A source fuses its own contribution at this precision too (wire_rounded), so every
// robot fuses bit-identical inputs.

#include <cstdint>

#include <Eigen/Core>

namespace hexplore::highlevel {

inline constexpr double kCentreQuantaPerM = 64.0;

// Centre coordinate in grid steps, and back.
int64_t centre_steps(double metres);
inline double centre_from_steps(int64_t steps) { return static_cast<double>(steps) / kCentreQuantaPerM; }

// Octahedral encoding of a unit normal in two signed bytes; decode gives a unit vector whose
// coordinates are exact floats (they travel as float). A zero vector encodes as +z.
struct PackedNormal {
  int8_t u = 0;
  int8_t v = 0;
};
PackedNormal pack_normal(const Eigen::Vector3d& n);
Eigen::Vector3d unpack_normal(PackedNormal p);

}  // namespace hexplore::highlevel
