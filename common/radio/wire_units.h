#pragma once
// Fixed-point units of the team messages on the radio. Positions travel in centimetres (robot
// bodies are tens of centimetres; safety margins are 10 cm), the centres of a team solution's
// task clusters in decimetres (they only measure how far a new route strays from the
// reference, in metres), speeds in centimetres per second, angles in 256ths of a turn. Every
// value is clamped to what its field can hold.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "common/transport/byte_codec.h"
#include "common/transport/roster.h"

namespace hexplore::radio {

inline constexpr double kCmPerM = 100.0;
inline constexpr double kDmPerM = 10.0;

// Metres as a whole number of 1/steps_per_m steps (0 for NaN and infinities, clamped to 10,000 km).
inline int64_t to_steps(double metres, double steps_per_m) {
  if (!std::isfinite(metres)) return 0;
  return static_cast<int64_t>(std::llround(std::clamp(metres, -1e7, 1e7) * steps_per_m));
}
inline int64_t to_cm(double metres) { return to_steps(metres, kCmPerM); }
inline double from_cm(int64_t cm) { return static_cast<double>(cm) / kCmPerM; }

// A point as three zigzag varints of 1/steps_per_m metres relative to `origin` (delta coding).
inline void write_fixed(transport::ByteWriter& w, const Eigen::Vector3d& p, const Eigen::Vector3d& origin,
                        double steps_per_m) {
  for (int a = 0; a < 3; ++a) w.svarint(to_steps(p[a], steps_per_m) - to_steps(origin[a], steps_per_m));
}
inline Eigen::Vector3d read_fixed(transport::ByteReader& r, const Eigen::Vector3d& origin, double steps_per_m) {
  Eigen::Vector3d p;
  // A step beyond twice the clamp of to_steps is malformed (and could overflow the sum).
  const auto max_step = static_cast<int64_t>(2e7 * steps_per_m);
  for (int a = 0; a < 3; ++a)
    p[a] = static_cast<double>(r.bounded_svarint(max_step) + to_steps(origin[a], steps_per_m)) / steps_per_m;
  return p;
}
// ... in centimetres (waypoints, supervoxel centres).
inline void write_cm(transport::ByteWriter& w, const Eigen::Vector3d& p, const Eigen::Vector3d& origin) {
  write_fixed(w, p, origin, kCmPerM);
}
inline Eigen::Vector3d read_cm(transport::ByteReader& r, const Eigen::Vector3d& origin) {
  return read_fixed(r, origin, kCmPerM);
}

// An angle in radians as a byte: 256 steps per turn (1.4 degrees).
inline uint8_t angle_byte(double radians) {
  if (!std::isfinite(radians)) return 0;
  const double turns = radians / (2.0 * M_PI);
  return static_cast<uint8_t>(static_cast<int64_t>(std::llround((turns - std::floor(turns)) * 256.0)) & 0xff);
}
inline double angle_from_byte(uint8_t b) {
  const double a = static_cast<double>(b) / 256.0 * 2.0 * M_PI;
  return a > M_PI ? a - 2.0 * M_PI : a;
}

// A robot id as a varint: 0 for "", slot + 2 for a robot on the roster, 1 followed by the id
// for one that is not (or without a roster). read_robot fails on a slot beyond the roster.
void write_robot(transport::ByteWriter& w, const transport::Roster* roster, const std::string& id);
bool read_robot(transport::ByteReader& r, const transport::Roster* roster, std::string& id);

}  // namespace hexplore::radio
