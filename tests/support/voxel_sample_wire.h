#pragma once
// A voxel sample as the mapping service would put it on the wire (perception::to_proto does it
// for the perception map's voxels; tests that make samples by hand need the same message).

#include "common/highlevel/voxel_sample.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::highlevel {

void to_proto(const VoxelSample& v, v1::Voxel* out);

}  // namespace hexplore::highlevel
