#pragma once
// Eigen <-> hexplore.v1.Vec3, for the team codecs.

#include <Eigen/Core>

#include "hexplore/v1/geometry.pb.h"

namespace hexplore::radio {

inline Eigen::Vector3d vec(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline void set(v1::Vec3* out, const Eigen::Vector3d& v) {
  out->set_x(v.x());
  out->set_y(v.y());
  out->set_z(v.z());
}

}  // namespace hexplore::radio
