// A VoxelDelta as the hlmap service takes it from its mapping service: refused at another
// resolution than the map's, else segmented into supervoxels (an update, or a replacement for
// a full snapshot) and logged as this robot's contribution. Input: flags byte, then payload.

#include <cmath>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/segmenter.h"
#include "common/highlevel/high_level_map.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::VoxelDelta delta;
  if (!fuzz::decode_payload(data, size, delta)) return 0;
  const highlevel::SegmenterParams params = highlevel::SegmenterParams::from(fuzz::team().params);
  if (std::abs(delta.resolution_m() - params.resolution_m) > 1e-9 * params.resolution_m) return 0;
  highlevel::SupervoxelSegmenter segmenter(params, highlevel::species_levels(fuzz::team()));
  highlevel::ContributionLog log("slugcat1");
  const auto samples = highlevel::voxel_samples(delta);
  const auto change = delta.full_snapshot() ? segmenter.replace_all(samples) : segmenter.update(samples);
  log.record(segmenter, change);
  log.take_increment();
  return 0;
}
