#include "tests/support/voxel_sample_wire.h"

namespace hexplore::highlevel {

void to_proto(const VoxelSample& v, v1::Voxel* out) {
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
  out->set_coverage_gap(static_cast<v1::CoverageGap>(v.gap));
}

}  // namespace hexplore::highlevel
