#include "common/perception/voxel_proto.h"

#include <cmath>
#include <cstring>

namespace hexplore::perception {

const char* to_string(ScanRejection r) {
  switch (r) {
    case ScanRejection::kNone: return "none";
    case ScanRejection::kSizeMismatch: return "size_mismatch";
    case ScanRejection::kBadOrigin: return "bad_origin";
  }
  return "unknown";
}

ScanRejection decode_scan(const v1::ScanFrame& frame, std::vector<float>& storage, ScanPoints& out) {
  const std::string& bytes = frame.points_xyz_f32();
  if (bytes.size() % 12 != 0 || bytes.size() / 12 != frame.point_count()) return ScanRejection::kSizeMismatch;
  const Eigen::Vector3d origin(frame.sensor_origin_m().x(), frame.sensor_origin_m().y(), frame.sensor_origin_m().z());
  if (!origin.allFinite()) return ScanRejection::kBadOrigin;
  // The wire format is little-endian float32, as is every platform this runs on.
  storage.resize(static_cast<size_t>(frame.point_count()) * 3);
  if (!bytes.empty()) std::memcpy(storage.data(), bytes.data(), bytes.size());
  out.sensor_origin = origin;
  out.xyz = storage.data();
  out.count = frame.point_count();
  out.max_range_m = std::isfinite(frame.max_range_m()) && frame.max_range_m() > 0.0 ? frame.max_range_m() : 0.0;
  return ScanRejection::kNone;
}

void to_proto(const VoxelView& v, v1::Voxel* out) {
  out->set_ix(v.key.x);
  out->set_iy(v.key.y);
  out->set_iz(v.key.z);
  out->set_mean_x(v.mean.x());
  out->set_mean_y(v.mean.y());
  out->set_mean_z(v.mean.z());
  out->set_normal_x(v.normal.x());
  out->set_normal_y(v.normal.y());
  out->set_normal_z(v.normal.z());
  out->set_flags(v.flags);
  out->set_low_risk_species_mask(v.low_risk_species_mask);
  out->set_coverage_gap(static_cast<v1::CoverageGap>(v.coverage_gap));
}

v1::VoxelDelta to_voxel_delta(const std::vector<VoxelView>& voxels, double resolution_m, bool full_snapshot) {
  v1::VoxelDelta delta;
  delta.set_resolution_m(resolution_m);
  delta.set_full_snapshot(full_snapshot);
  delta.mutable_voxels()->Reserve(static_cast<int>(voxels.size()));
  for (const VoxelView& v : voxels) to_proto(v, delta.add_voxels());
  return delta;
}

v1::OccupiedVoxels to_occupied_voxels(const std::vector<VoxelView>& voxels, double resolution_m) {
  v1::OccupiedVoxels out;
  out.set_resolution_m(resolution_m);
  out.mutable_keys_xyz()->Reserve(static_cast<int>(voxels.size() * 3));
  for (const VoxelView& v : voxels) {
    out.add_keys_xyz(v.key.x);
    out.add_keys_xyz(v.key.y);
    out.add_keys_xyz(v.key.z);
  }
  return out;
}

}  // namespace hexplore::perception
