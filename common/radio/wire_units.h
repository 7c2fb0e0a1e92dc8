#pragma once
// Fixed-point units of the team messages on the radio. Positions travel in centimetres (robot
// bodies are tens of centimetres; safety margins are 10 cm), speeds in centimetres per second,
// angles in 256ths of a turn. Every value is clamped to what its field can hold.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "common/transport/byte_codec.h"
#include "common/transport/roster.h"

namespace hexplore::radio {

inline constexpr double kCmPerM = 100.0;

inline int64_t to_cm(double metres) {
  if (!std::isfinite(metres)) return 0;
  return static_cast<int64_t>(std::llround(std::clamp(metres, -1e7, 1e7) * kCmPerM));
}
inline double from_cm(int64_t cm) { return static_cast<double>(cm) / kCmPerM; }

// A point as three zigzag varints of centimetres relative to `origin` (delta coding).
inline void write_cm(transport::ByteWriter& w, const Eigen::Vector3d& p, const Eigen::Vector3d& origin) {
  for (int a = 0; a < 3; ++a) w.svarint(to_cm(p[a]) - to_cm(origin[a]));
}
inline Eigen::Vector3d read_cm(transport::ByteReader& r, const Eigen::Vector3d& origin) {
  Eigen::Vector3d p;
  for (int a = 0; a < 3; ++a) p[a] = from_cm(r.svarint() + to_cm(origin[a]));
  return p;
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
