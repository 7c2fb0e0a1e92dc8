#include "common/sim/mesh_builder.h"

#include <cmath>

#include <Eigen/Geometry>

namespace hexplore::sim {

uint32_t MeshBuilder::vertex(const Eigen::Vector3d& v) {
  mesh_.vertices.push_back(v.cast<float>());
  return static_cast<uint32_t>(mesh_.vertices.size() - 1);
}

void MeshBuilder::quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  mesh_.triangles.push_back({a, b, c});
  mesh_.triangles.push_back({a, c, d});
}

// Corners ordered: bottom face 0-1-2-3 counter-clockwise seen from above, top face 4-5-6-7
// above them. Faces wound outward for a convex solid.
void MeshBuilder::hexahedron(const Eigen::Vector3d (&c)[8]) {
  uint32_t i[8];
  for (int k = 0; k < 8; ++k) i[k] = vertex(c[k]);
  quad(i[0], i[3], i[2], i[1]);  // bottom
  quad(i[4], i[5], i[6], i[7]);  // top
  quad(i[0], i[1], i[5], i[4]);
  quad(i[1], i[2], i[6], i[5]);
  quad(i[2], i[3], i[7], i[6]);
  quad(i[3], i[0], i[4], i[7]);
}

void MeshBuilder::box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  if (!((hi - lo).array() > 1e-9).all()) return;
  const Eigen::Vector3d c[8] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()},
                                {lo.x(), hi.y(), lo.z()}, {lo.x(), lo.y(), hi.z()}, {hi.x(), lo.y(), hi.z()},
                                {hi.x(), hi.y(), hi.z()}, {lo.x(), hi.y(), hi.z()}};
  hexahedron(c);
}

void MeshBuilder::oriented_box(const Eigen::Vector3d& center, const Eigen::Vector3d& half, double yaw, double pitch,
                               double roll) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const double sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
  const double sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
  const double sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  Eigen::Vector3d c[8];
  for (int k = 0; k < 8; ++k) c[k] = center + r * Eigen::Vector3d(sx[k] * half.x(), sy[k] * half.y(), sz[k] * half.z());
  hexahedron(c);
}

void MeshBuilder::wedge(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Heading up) {
  if (!((hi - lo).array() > 1e-9).all()) return;
  // Top corner heights by corner (0..3 counter-clockwise from (lo.x, lo.y)).
  double top[4] = {0, 0, 0, 0};
  const double a = lo.z() + 1e-3, b = hi.z();  // a sliver of height at the low end keeps it a solid
  switch (up) {
    case Heading::kPlusX: top[0] = a; top[1] = b; top[2] = b; top[3] = a; break;
    case Heading::kMinusX: top[0] = b; top[1] = a; top[2] = a; top[3] = b; break;
    case Heading::kPlusY: top[0] = a; top[1] = a; top[2] = b; top[3] = b; break;
    case Heading::kMinusY: top[0] = b; top[1] = b; top[2] = a; top[3] = a; break;
  }
  const Eigen::Vector3d c[8] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()},
                                {lo.x(), hi.y(), lo.z()}, {lo.x(), lo.y(), top[0]}, {hi.x(), lo.y(), top[1]},
                                {hi.x(), hi.y(), top[2]}, {lo.x(), hi.y(), top[3]}};
  hexahedron(c);
}

void MeshBuilder::stairs(const Eigen::Vector3d& start, Heading up, double width, int steps, double rise, double run) {
  for (int s = 0; s < steps; ++s) {
    const double near = s * run, far = (s + 1) * run;
    const double top = start.z() + (s + 1) * rise;
    Eigen::Vector3d lo, hi;
    switch (up) {
      case Heading::kPlusX:
        lo = {start.x() + near, start.y() - width / 2, start.z()};
        hi = {start.x() + far, start.y() + width / 2, top};
        break;
      case Heading::kMinusX:
        lo = {start.x() - far, start.y() - width / 2, start.z()};
        hi = {start.x() - near, start.y() + width / 2, top};
        break;
      case Heading::kPlusY:
        lo = {start.x() - width / 2, start.y() + near, start.z()};
        hi = {start.x() + width / 2, start.y() + far, top};
        break;
      case Heading::kMinusY:
        lo = {start.x() - width / 2, start.y() - far, start.z()};
        hi = {start.x() + width / 2, start.y() - near, top};
        break;
    }
    box(lo, hi);
  }
}

void MeshBuilder::plane(double x0, double y0, double x1, double y1, double z) {
  const uint32_t a = vertex({x0, y0, z}), b = vertex({x1, y0, z}), c = vertex({x1, y1, z}), d = vertex({x0, y1, z});
  quad(a, b, c, d);
}

}  // namespace hexplore::sim
