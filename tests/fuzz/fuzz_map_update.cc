// The high-level map on the radio and inside a robot: a teammate's MapIncrement or a
// MapSnapshot (a repair reply) as the hlmap service takes it (in order through PeerSync, then
// fused), and a FusedMapUpdate as the planning service applies it to its map.
// Input: byte 0 picks the message (0: increment, 1: snapshot, 2: fused update), then the flags
// byte and the payload.

#include "common/highlevel/high_level_map.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/peer_sync.h"
#include "tests/fuzz/fuzz_team.h"

namespace {

using namespace hexplore;

void fuse(const std::vector<highlevel::SourcedUpdate>& ready) {
  highlevel::MapFusion fusion(highlevel::species_levels(fuzz::team()));
  for (const auto& u : ready) fusion.apply(u.source, u.update);
  fusion.take_changes();
  fusion.map().snapshot();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t which = data[0] % 3;
  ++data;
  --size;
  if (which == 0) {
    v1::MapIncrement inc;
    if (!fuzz::decode_payload(data, size, inc)) return 0;
    highlevel::PeerSync sync("slugcat1");
    fuse(sync.on_increment(highlevel::from_proto(inc)));
  } else if (which == 1) {
    v1::MapSnapshot snap;
    if (!fuzz::decode_payload(data, size, snap)) return 0;
    highlevel::PeerSync sync("slugcat1");
    fuse(sync.on_snapshot(highlevel::from_proto(snap)));
  } else {
    v1::FusedMapUpdate update;
    if (!fuzz::decode_payload(data, size, update)) return 0;
    highlevel::HighLevelMap map(highlevel::species_levels(fuzz::team()));
    map.apply(highlevel::from_proto(update));
  }
  return 0;
}
