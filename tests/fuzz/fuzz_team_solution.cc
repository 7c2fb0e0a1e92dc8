// A teammate's TeamSolution (team/plan) as the planning service takes it: its sequences
// become a reference solution for the next round, its given-up targets merge into the ledger.
// Input: flags byte, then the payload.

#include "common/planning/give_up_ledger.h"
#include "common/planning/plan_proto.h"
#include "tests/fuzz/fuzz_team.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  v1::TeamSolution solution;
  if (!fuzz::decode_payload(data, size, solution)) return 0;
  if (solution.sequences_size() > 0) {
    const planning::ReferenceSolution reference = planning::reference_from_proto(solution, "mr1000a");
    reference.max_length();
    reference.route_of("slugcat1");
  }
  planning::GiveUpLedger ledger;
  const auto& keys = solution.given_up_supervoxels();
  const auto& counts = solution.given_up_voxel_counts();
  for (int i = 0; i < keys.size(); ++i) ledger.merge(keys[i], i < counts.size() ? int(counts[i]) : 0);
  return 0;
}
