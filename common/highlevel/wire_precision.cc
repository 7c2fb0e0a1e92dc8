#include "common/highlevel/wire_precision.h"

#include <algorithm>
#include <cmath>

namespace hexplore::highlevel {
namespace {

constexpr float kScale = 127.0f;

// By the sign bit: a fold that produced -0 must unfold with the same sign.
float sign_not_zero(float v) { return std::signbit(v) ? -1.0f : 1.0f; }

}  // namespace

int64_t centre_steps(double metres) { return static_cast<int64_t>(std::llround(metres * kCentreQuantaPerM)); }

PackedNormal pack_normal(const Eigen::Vector3d& n_in) {
  const Eigen::Vector3f n = n_in.cast<float>();
  const float l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
  if (!(l1 > 1e-12f) || !std::isfinite(l1)) return {};
  float x = n.x() / l1, y = n.y() / l1;
  if (n.z() < 0.0f) {
    // Fold the lower hemisphere over the diagonals.
    const float fx = (1.0f - std::abs(y)) * sign_not_zero(x);
    const float fy = (1.0f - std::abs(x)) * sign_not_zero(y);
    x = fx;
    y = fy;
  }
  auto q = [](float c) { return static_cast<int8_t>(std::clamp(std::lround(c * kScale), -127L, 127L)); };
  return {q(x), q(y)};
}

Eigen::Vector3d unpack_normal(PackedNormal p) {
  float x = static_cast<float>(p.u) / kScale;
  float y = static_cast<float>(p.v) / kScale;
  const float z = 1.0f - std::abs(x) - std::abs(y);
  if (z < 0.0f) {
    const float fx = (1.0f - std::abs(y)) * sign_not_zero(x);
    const float fy = (1.0f - std::abs(x)) * sign_not_zero(y);
    x = fx;
    y = fy;
  }
  Eigen::Vector3f n(x, y, z);
  n.normalize();
  return n.cast<double>();
}

}  // namespace hexplore::highlevel
