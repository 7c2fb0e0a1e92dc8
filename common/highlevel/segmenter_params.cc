#include "common/highlevel/segmenter_params.h"

#include <stdexcept>
#include <string>

#include "common/core/team_config.h"

namespace hexplore::highlevel {

SegmenterParams SegmenterParams::from(const core::AlgorithmParams& params) {
  SegmenterParams out;
  out.resolution_m = params.map_resolution_m;
  out.eta_s_m = params.eta_s_m;
  out.eta_e_m = params.eta_e_m;
  out.min_ise_patch_voxels = params.min_ise_patch_voxels;
  return out;
}

void SegmenterParams::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("SegmenterParams: " + what); };
  if (!(resolution_m > 0.0)) fail("resolution_m must be > 0, got " + std::to_string(resolution_m));
  if (!(eta_s_m >= resolution_m)) fail("eta_s_m must be >= resolution_m, got " + std::to_string(eta_s_m));
  if (!(eta_e_m >= 0.0)) fail("eta_e_m must be >= 0, got " + std::to_string(eta_e_m));
  if (max_hops < 0) fail("max_hops must be >= 0, got " + std::to_string(max_hops));
  if (max_hops * resolution_m > eta_s_m) fail("max_hops * resolution_m must not exceed eta_s_m");
  if (min_ise_patch_voxels < 1) fail("min_ise_patch_voxels must be >= 1, got " + std::to_string(min_ise_patch_voxels));
}

}  // namespace hexplore::highlevel
