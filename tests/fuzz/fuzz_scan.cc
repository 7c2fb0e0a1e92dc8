// A ScanFrame as the mapping service takes it from its simulator or driver: decoded and
// checked (point count against byte length, finite sensor origin), then integrated into a
// perception map with the team's parameters. Input: payload flags byte, then the payload.

#include <vector>

#include "common/perception/map_params.h"
#include "common/perception/perception_map.h"
#include "common/perception/voxel_proto.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::ScanFrame frame;
  if (!fuzz::decode_payload(data, size, frame)) return 0;
  std::vector<float> storage;
  perception::ScanPoints scan;
  if (perception::decode_scan(frame, storage, scan) != perception::ScanRejection::kNone) return 0;
  static const perception::MapParams params = perception::make_map_params(fuzz::team(), "slugcat1");
  perception::PerceptionMap map(params);
  map.integrate(scan, {});
  map.take_changes();
  return 0;
}
