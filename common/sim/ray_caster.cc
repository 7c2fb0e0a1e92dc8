#include "common/sim/ray_caster.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <embree3/rtcore.h>

#include "common/sim/scene_error.h"

namespace hexplore::sim {

struct RayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw SceneError("embree", std::string(what) + " failed (error " + std::to_string(e) + ")");
}

}  // namespace

RayCaster::RayCaster(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  if (mesh.empty()) throw SceneError("ray caster", "the scene mesh has no triangles");
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw SceneError("embree", "cannot create a device (error " +
                                                     std::to_string(rtcGetDeviceError(nullptr)) + ")");
  impl_->scene = rtcNewScene(impl_->device);
  // Robust traversal: rays grazing shared edges of coincident boxes must not slip through.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), mesh.vertices.size()));
  auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(uint32_t), mesh.triangles.size()));
  check(impl_->device, "allocating geometry buffers");
  for (size_t i = 0; i < mesh.vertices.size(); ++i) std::memcpy(v + 3 * i, mesh.vertices[i].data(), 12);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (auto k : mesh.triangles[i])
      if (k >= mesh.vertices.size())
        throw SceneError("ray caster", "triangle " + std::to_string(i) + " references a missing vertex");
    std::memcpy(idx + 3 * i, mesh.triangles[i].data(), 12);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(impl_->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(impl_->scene);
  check(impl_->device, "building the scene");
  bounds_ = mesh.bounds();
  triangles_ = mesh.triangles.size();
}

RayCaster::~RayCaster() = default;

float RayCaster::cast(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_near, float t_far) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray.org_x = o.x(); rh.ray.org_y = o.y(); rh.ray.org_z = o.z();
  rh.ray.dir_x = d.x(); rh.ray.dir_y = d.y(); rh.ray.dir_z = d.z();
  rh.ray.tnear = t_near;
  rh.ray.tfar = t_far;
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &ctx, &rh);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kMiss : rh.ray.tfar;
}

bool RayCaster::occluded(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_near, float t_far) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray;
  ray.org_x = o.x(); ray.org_y = o.y(); ray.org_z = o.z();
  ray.dir_x = d.x(); ray.dir_y = d.y(); ray.dir_z = d.z();
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  rtcOccluded1(impl_->scene, &ctx, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

void RayCaster::cast_fan(const Eigen::Vector3f& o, std::span<const Eigen::Vector3f> dirs, float t_near, float t_far,
                         std::span<float> out) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // a fan from one origin is coherent
  alignas(64) RTCRayHit16 rh;
  alignas(64) int valid[16];
  const size_t n = std::min(dirs.size(), out.size());
  for (size_t base = 0; base < n; base += 16) {
    const size_t count = std::min<size_t>(16, n - base);
    for (size_t k = 0; k < 16; ++k) {
      const bool live = k < count;
      valid[k] = live ? -1 : 0;
      const Eigen::Vector3f& d = dirs[live ? base + k : base];
      rh.ray.org_x[k] = o.x(); rh.ray.org_y[k] = o.y(); rh.ray.org_z[k] = o.z();
      rh.ray.dir_x[k] = d.x(); rh.ray.dir_y[k] = d.y(); rh.ray.dir_z[k] = d.z();
      rh.ray.tnear[k] = t_near;
      rh.ray.tfar[k] = t_far;
      rh.ray.time[k] = 0.0f;
      rh.ray.mask[k] = 0xFFFFFFFFu;
      rh.ray.id[k] = static_cast<unsigned>(k);
      rh.ray.flags[k] = 0;
      rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, impl_->scene, &ctx, &rh);
    for (size_t k = 0; k < count; ++k)
      out[base + k] = rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID ? kMiss : rh.ray.tfar[k];
  }
}

}  // namespace hexplore::sim
