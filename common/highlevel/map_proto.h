#pragma once
// Conversions between the wire messages (proto/voxels.proto, proto/hlmap.proto) and the
// library's plain types. The only file of the library that knows protobuf.

#include <vector>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/high_level_map.h"
#include "common/highlevel/voxel_sample.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::highlevel {

VoxelSample from_proto(const v1::Voxel& v);
// The delta's voxels, without the malformed ones (a mean off the world or not finite, a
// normal that is not a unit vector or none: core/world_bounds.h), whose number goes to
// `malformed` when given. Segmenting such a voxel is undefined behaviour (found by tests/fuzz).
std::vector<VoxelSample> voxel_samples(const v1::VoxelDelta& delta, size_t* malformed = nullptr);

Supervoxel from_proto(const v1::Supervoxel& s);
void to_proto(const Supervoxel& s, v1::Supervoxel* out);

// Edge lengths on the wire are the distance between the endpoints' centres in `centres_of`
// (a map or contribution); 0 when an endpoint is unknown there.
v1::MapIncrement to_increment(const SourcedUpdate& inc, const Contribution& current);
v1::MapSnapshot to_snapshot(const SourcedUpdate& snap, const Contribution& current);
// From the wire, supervoxels whose centre or normal is malformed (as for voxels above) are left
// out and counted in MapUpdate::malformed.
SourcedUpdate from_proto(const v1::MapIncrement& inc);
SourcedUpdate from_proto(const v1::MapSnapshot& snap);

v1::FusedMapUpdate to_fused_update(const MapUpdate& update, const HighLevelMap& map);
MapUpdate from_proto(const v1::FusedMapUpdate& update);

}  // namespace hexplore::highlevel
