#pragma once
// Builds scene meshes from simple solids (boxes, oriented boxes, wedges, stairs). Every
// solid is closed, so both sides of thin parts are hit and sampled.

#include <Eigen/Core>

#include "common/sim/triangle_mesh.h"

namespace hexplore::sim {

// Horizontal direction along which a ramp rises or a staircase climbs.
enum class Heading { kPlusX, kMinusX, kPlusY, kMinusY };

class MeshBuilder {
 public:
  // Axis-aligned box; ignored when any extent is not positive.
  void box(const Eigen::Vector3d& min, const Eigen::Vector3d& max);
  // Box of half extents `half` centred at `center`, rotated by yaw, then pitch and roll (rad).
  void oriented_box(const Eigen::Vector3d& center, const Eigen::Vector3d& half, double yaw, double pitch = 0.0,
                    double roll = 0.0);
  // Solid wedge in the box [min, max]: its top rises from min.z to max.z along `up`.
  void wedge(const Eigen::Vector3d& min, const Eigen::Vector3d& max, Heading up);
  // Solid staircase: `steps` steps of `rise` x `run`, `width` wide, starting at `start`
  // (the foot of the first riser, centre of its width, at the base height) climbing along `up`.
  void stairs(const Eigen::Vector3d& start, Heading up, double width, int steps, double rise, double run);
  // Horizontal rectangle (two triangles), e.g. a ground plane.
  void plane(double x0, double y0, double x1, double y1, double z);

  const TriangleMesh& mesh() const { return mesh_; }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  uint32_t vertex(const Eigen::Vector3d& v);
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
  void hexahedron(const Eigen::Vector3d (&corners)[8]);

  TriangleMesh mesh_;
};

}  // namespace hexplore::sim
