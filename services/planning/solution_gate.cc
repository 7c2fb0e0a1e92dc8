#include "services/planning/solution_gate.h"

namespace hexplore::planning_service {

std::string SolutionGate::signature(const v1::TeamSolution& solution) {
  // Route lengths, centres and fitness change with every robot's position; what the team
  // acts on is who takes which clusters in which order.
  std::string s = solution.planner();
  for (const auto& seq : solution.sequences()) {
    s += '|';
    s += seq.robot_id();
    for (uint64_t id : seq.cluster_ids()) s.append(reinterpret_cast<const char*>(&id), sizeof id);
  }
  return s;
}

bool SolutionGate::should_send(const v1::TeamSolution& solution, bool news, double now_s) {
  const bool with_sequences = solution.sequences_size() > 0;
  std::string sig = with_sequences ? signature(solution) : std::string();
  const bool changed = solution.planner() != sent_planner_ || (with_sequences && sig != sent_signature_);
  const bool send = !sent_any_ || news || changed || now_s - sent_at_s_ >= refresh_s_;
  if (send) {
    sent_any_ = true;
    sent_at_s_ = now_s;
    sent_planner_ = solution.planner();
    if (with_sequences) sent_signature_ = std::move(sig);
  }
  return send;
}

}  // namespace hexplore::planning_service
