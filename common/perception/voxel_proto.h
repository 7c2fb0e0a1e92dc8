#pragma once
// Conversions between the perception map and the v1 wire messages: ScanFrame in (with the
// checks a mapping service needs before trusting a frame), VoxelDelta / OccupiedVoxels out.

#include <string>
#include <vector>

#include "common/perception/perception_map.h"
#include "hexplore/v1/scan.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::perception {

// Why a ScanFrame was refused before integration (label values of a rejection counter).
enum class ScanRejection { kNone, kSizeMismatch, kBadOrigin };
const char* to_string(ScanRejection r);

// Points of `frame` decoded into `storage` and described by `out` (which points into storage).
// Refuses a frame whose point_count disagrees with its byte length or whose sensor origin is
// not finite; non-finite points are left in and counted by integrate().
ScanRejection decode_scan(const v1::ScanFrame& frame, std::vector<float>& storage, ScanPoints& out);

void to_proto(const VoxelView& v, v1::Voxel* out);
v1::VoxelDelta to_voxel_delta(const std::vector<VoxelView>& voxels, double resolution_m, bool full_snapshot);
v1::OccupiedVoxels to_occupied_voxels(const std::vector<VoxelView>& voxels, double resolution_m);

}  // namespace hexplore::perception
