// A MissionCommand (team/mission) as every service takes it: whether it is for this robot,
// and the mission state it moves the robot to. Input: flags byte, then the payload.

#include "common/service/mission_state.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::MissionCommand command;
  if (!fuzz::decode_payload(data, size, command)) return 0;
  service::MissionState state(true);
  state.apply(command, "slugcat1");
  service::addressed_to(command, "slugcat1");
  return 0;
}
