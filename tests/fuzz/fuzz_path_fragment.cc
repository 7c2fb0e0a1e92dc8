// A teammate's PathFragment (team/path) as the safety service takes it: converted to the
// safety library's fragment, with the sender's body box where the radio left it out, and the
// path and distances the conflict checks read. Input: flags byte, then the payload.

#include "common/safety/fragment.h"
#include "common/safety/fragment_proto.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::PathFragment message;
  if (!fuzz::decode_payload(data, size, message)) return 0;
  safety::Fragment fragment = safety::from_proto(message, "mr1000a");
  if (!message.has_body_box_m())
    safety::body_box_any_yaw(fragment.position_m, Eigen::Vector3d(0.5, 0.35, 0.4), fragment.box_min_m,
                             fragment.box_max_m);
  fragment.path();
  fragment.body_radius_m();
  fragment.distance_to(Eigen::Vector3d(1.0, 2.0, 0.0));
  return 0;
}
