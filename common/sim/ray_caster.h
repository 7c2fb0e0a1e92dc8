#pragma once
// Ray casting against a static scene with Intel Embree 3. The scene is built and committed
// once in the constructor; every query is const and thread-safe. Faces are two-sided.

#include <limits>
#include <memory>
#include <span>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/sim/triangle_mesh.h"

namespace hexplore::sim {

class RayCaster {
 public:
  static constexpr float kMiss = std::numeric_limits<float>::infinity();

  // Throws SceneError when the mesh is empty or Embree fails.
  explicit RayCaster(const TriangleMesh& mesh);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Distance to the first surface along the unit direction within [t_near, t_far], or kMiss.
  float cast(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir_unit, float t_near, float t_far) const;
  // Whether anything lies on the segment [t_near, t_far] (cheaper than cast).
  bool occluded(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir_unit, float t_near, float t_far) const;
  // Many rays from one origin, 16 at a time: distances[i] for dirs[i] (kMiss when nothing).
  void cast_fan(const Eigen::Vector3f& origin, std::span<const Eigen::Vector3f> dirs_unit, float t_near,
                float t_far, std::span<float> distances) const;

  const Eigen::AlignedBox3f& bounds() const { return bounds_; }
  size_t triangle_count() const { return triangles_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Eigen::AlignedBox3f bounds_;
  size_t triangles_ = 0;
};

}  // namespace hexplore::sim
