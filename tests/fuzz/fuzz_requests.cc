// The requests a service answers (ROUTER sockets): a map repair (hlmap), the fused map
// (hlmap), open targets (planning), occupied voxels (mapping), as the responder decodes them
// before a handler sees them. Input: byte 0 picks the request, then flags byte and payload.

#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/voxels.pb.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  if (size < 1) return 0;
  const uint8_t which = data[0] % 4;
  ++data;
  --size;
  if (which == 0) {
    v1::MapRepairRequest request;
    if (fuzz::decode_payload(data, size, request)) fuzz::team().find_robot(request.source_robot());
  } else if (which == 1) {
    v1::FusedMapRequest request;
    fuzz::decode_payload(data, size, request);
  } else if (which == 2) {
    v1::OpenTargetsRequest request;
    fuzz::decode_payload(data, size, request);
  } else {
    v1::OccupiedVoxelsRequest request;
    fuzz::decode_payload(data, size, request);
  }
  return 0;
}
